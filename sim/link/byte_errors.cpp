// Random byte corruption; see byte_errors.hpp.
#include "sim/link/byte_errors.hpp"

namespace driftlab::sim {

void ByteErrors::process(Packet& packet, LinkCounters& counters) {
    if (rate_ == 0.0) return;
    for (TimedByte& b : packet.bytes) {
        if (rng_.uniform() >= rate_) continue;
        const auto mask = static_cast<std::uint8_t>(1u + rng_.next_u64() % 255u);
        b.value = static_cast<std::uint8_t>(b.value ^ mask);
        ++counters.bytes_corrupted;
        packet.damaged = true;
    }
}

}  // namespace driftlab::sim
