// Fixed latency of a direction (radio modem buffering, USB polling): every byte arrives `latency_s` later than
// its UART finished it. Order is preserved. docs/sim.md §Link.
#pragma once

#include "sim/link/link.hpp"

namespace driftlab::sim {

class Latency final : public LinkStage {
public:
    explicit Latency(double latency_s) : latency_s_(latency_s) {}
    void process(Packet& packet, LinkCounters& counters) override;

private:
    double latency_s_;
};

}  // namespace driftlab::sim
