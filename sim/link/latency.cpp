// Fixed delay; see latency.hpp.
#include "sim/link/latency.hpp"

namespace driftlab::sim {

void Latency::process(Packet& packet, LinkCounters& /*counters*/) {
    for (TimedByte& b : packet.bytes) b.t_s += latency_s_;
}

}  // namespace driftlab::sim
