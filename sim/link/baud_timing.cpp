// UART serialisation; see baud_timing.hpp.
#include "sim/link/baud_timing.hpp"

#include <algorithm>

namespace driftlab::sim {

void BaudTiming::process(Packet& packet, LinkCounters& /*counters*/) {
    for (TimedByte& b : packet.bytes) {
        line_free_s_ = std::max(b.t_s, line_free_s_) + byte_time_s_;
        b.t_s = line_free_s_;
    }
}

}  // namespace driftlab::sim
