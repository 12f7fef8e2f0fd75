// Native target; see native_target.hpp.
#include "sim/hil/native_target.hpp"

#include <algorithm>
#include <cmath>

namespace driftlab::sim {

namespace {

constexpr double kTickHz = static_cast<double>(fw::kTickHz);

double seconds_of(std::uint64_t ticks) { return static_cast<double>(ticks) / kTickHz; }

// The last tick whose instant seconds_of(tick) is <= t_s. Rounding in t_s · kTickHz alone could land one tick
// short of an instant that next_conversion_s() reported, and the loop would never reach that conversion.
std::uint64_t ticks_at_or_before(double t_s) {
    auto k = static_cast<std::uint64_t>(std::max(0.0, std::floor(t_s * kTickHz)));
    while (seconds_of(k + 1) <= t_s) ++k;
    while (k > 0 && seconds_of(k) > t_s) --k;
    return k;
}

}  // namespace

NativeTarget::NativeTarget(std::span<const std::uint8_t> eeprom, const DieTemperature& die) : die_(die) {
    board_.load_eeprom(eeprom.data(), eeprom.size());
    board_.set_die_temperature_code(die_.code(0.0));
    firmware_.start();
}

std::optional<double> NativeTarget::next_conversion_s() const {
    if (!board_.armed()) return std::nullopt;
    return seconds_of(board_.next_conversion_time_ticks());
}

double NativeTarget::time_s() const { return seconds_of(board_.time_ticks()); }

void NativeTarget::advance_to(double t_s, ConversionSource& source, std::vector<TxChunk>& tx) {
    const std::uint64_t target_ticks = std::max(ticks_at_or_before(t_s), board_.time_ticks());
    while (board_.next_conversion_time_ticks() <= target_ticks) {
        const std::uint64_t trigger = board_.next_conversion_time_ticks();
        board_.set_time_ticks(trigger);
        if (board_.temperature_due()) board_.set_die_temperature_code(die_.code(seconds_of(trigger)));
        // A full conversion ring loses the conversion as on the chip; the firmware counts it from the tick gap.
        static_cast<void>(board_.convert(source.code(board_.next_channel(), seconds_of(trigger))));
        ++conversions_;
        board_.service(firmware_);
        drain_tx(tx);
    }
    board_.set_time_ticks(target_ticks);
}

void NativeTarget::receive(std::span<const std::uint8_t> bytes, std::vector<TxChunk>& tx) {
    // Hand bytes over at most a ring's worth at a time with the main loop in between, as the chip's main loop
    // keeps up with a UART: only a burst larger than the RX ring between two loop passes would overflow.
    std::size_t done = 0;
    while (done < bytes.size()) {
        const std::size_t n = std::min<std::size_t>(bytes.size() - done, fw::kRxRingCapacity);
        done += board_.receive(bytes.data() + done, n);
        board_.service(firmware_);
        drain_tx(tx);
    }
}

void NativeTarget::drain_tx(std::vector<TxChunk>& tx) {
    if (board_.tx_pending() == 0) return;
    TxChunk chunk{time_s(), std::vector<std::uint8_t>(board_.tx_pending())};
    chunk.bytes.resize(board_.transmit(chunk.bytes.data(), chunk.bytes.size()));
    tx.push_back(std::move(chunk));
}

}  // namespace driftlab::sim
