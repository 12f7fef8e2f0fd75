// Dropped bytes: each byte is independently lost with probability `rate` (a receiver overrun, a radio symbol
// that never decodes); the bytes around it close up. docs/sim.md §Link.
#pragma once

#include "sim/link/link.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::sim {

class DroppedBytes final : public LinkStage {
public:
    DroppedBytes(double rate, Rng rng) : rate_(rate), rng_(rng) {}
    void process(Packet& packet, LinkCounters& counters) override;

private:
    double rate_;
    Rng rng_;
};

}  // namespace driftlab::sim
