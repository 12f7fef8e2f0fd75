// `byte_errors`: each byte independently arrives corrupted with probability `rate`; a corrupted byte is XORed
// with a uniformly drawn non-zero mask, so it always differs from the byte sent. docs/sim.md §Link.
#pragma once

#include "sim/link/link.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::sim {

class ByteErrors final : public LinkStage {
public:
    ByteErrors(double rate, Rng rng) : rate_(rate), rng_(rng) {}
    void process(Packet& packet, LinkCounters& counters) override;

private:
    double rate_;
    Rng rng_;
};

}  // namespace driftlab::sim
