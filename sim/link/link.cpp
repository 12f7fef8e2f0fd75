// One direction's pipeline and its receiver queue; see link.hpp.
#include "sim/link/link.hpp"

#include "sim/link/baud_timing.hpp"
#include "sim/link/byte_errors.hpp"
#include "sim/link/dropped_bytes.hpp"
#include "sim/link/gilbert_elliott.hpp"
#include "sim/link/latency.hpp"
#include "sim/model/streams.hpp"

namespace driftlab::sim {

namespace {

// Substream offsets of the random behaviours within a direction.
constexpr std::uint64_t kPacketLossStream = 0;
constexpr std::uint64_t kDroppedBytesStream = 1;
constexpr std::uint64_t kByteErrorsStream = 2;

}  // namespace

LinkDirection::LinkDirection(double baud, const DirectionParams& params, std::uint64_t seed,
                             std::uint64_t stream_base) {
    // Physical order: the sender's UART clocks every byte out, the air loses or garbles some, the receiver's
    // modem adds its delay.
    stages_.push_back(std::make_unique<BaudTiming>(baud));
    stages_.push_back(std::make_unique<GilbertElliott>(params.packet_loss, Rng(seed, stream_base + kPacketLossStream)));
    stages_.push_back(
        std::make_unique<DroppedBytes>(params.byte_drop_rate, Rng(seed, stream_base + kDroppedBytesStream)));
    stages_.push_back(std::make_unique<ByteErrors>(params.byte_error_rate, Rng(seed, stream_base + kByteErrorsStream)));
    stages_.push_back(std::make_unique<Latency>(params.latency_s));
}

void LinkDirection::send(double t_s, std::span<const std::uint8_t> packet) {
    Packet p;
    p.bytes.reserve(packet.size());
    for (std::uint8_t v : packet) p.bytes.push_back({t_s, v});
    ++counters_.packets_sent;
    counters_.bytes_sent += packet.size();
    for (auto& stage : stages_) stage->process(p, counters_);
    if (p.damaged) ++counters_.packets_damaged;
    in_flight_.insert(in_flight_.end(), p.bytes.begin(), p.bytes.end());
}

std::optional<double> LinkDirection::next_arrival_s() const {
    if (in_flight_.empty()) return std::nullopt;
    return in_flight_.front().t_s;
}

void LinkDirection::deliver_until(double t_s, std::vector<std::uint8_t>& out) {
    // Arrival times are non-decreasing: serialisation keeps order and the latency is the same for every byte.
    while (!in_flight_.empty() && in_flight_.front().t_s <= t_s) {
        out.push_back(in_flight_.front().value);
        in_flight_.pop_front();
        ++counters_.bytes_delivered;
    }
}

Link::Link(const LinkParams& params, std::uint64_t seed)
    : to_host_(params.baud, params.to_host, seed, kToHostStreamBase),
      to_firmware_(params.baud, params.to_firmware, seed, kToFirmwareStreamBase) {}

}  // namespace driftlab::sim
