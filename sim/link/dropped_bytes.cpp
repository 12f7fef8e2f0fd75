// Independent byte drops; see dropped_bytes.hpp.
#include "sim/link/dropped_bytes.hpp"

#include <algorithm>

namespace driftlab::sim {

void DroppedBytes::process(Packet& packet, LinkCounters& counters) {
    if (rate_ == 0.0) return;
    const auto before = packet.bytes.size();
    std::erase_if(packet.bytes, [this](const TimedByte&) { return rng_.uniform() < rate_; });
    const auto dropped = before - packet.bytes.size();
    counters.bytes_dropped += dropped;
    if (dropped > 0) packet.damaged = true;
}

}  // namespace driftlab::sim
