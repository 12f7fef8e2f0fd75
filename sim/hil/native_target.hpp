// The native target: the firmware core (firmware/core) on the native port's NativeBoard, in virtual time.
// Ticks are the firmware's 250 kHz; an instant in seconds maps to the last whole tick at or before it.
#pragma once

#include <memory>
#include <span>

#include "firmware/core/firmware.hpp"
#include "firmware/port/native/native_board.hpp"
#include "sim/hil/die_temperature.hpp"
#include "sim/hil/emulated_board.hpp"

namespace driftlab::sim {

class NativeTarget final : public EmulatedBoard {
public:
    /// Powers the board on at t = 0 with `eeprom` in its EEPROM (empty: erased) and its die at `die`'s temperature:
    /// the firmware starts and arms its default schedule. Only one NativeTarget may live on a thread at a time
    /// (NativeBoard installs itself as the thread's HAL).
    explicit NativeTarget(std::span<const std::uint8_t> eeprom = {}, const DieTemperature& die = {});

    std::optional<double> next_conversion_s() const override;
    void advance_to(double t_s, ConversionSource& source, std::vector<TxChunk>& tx) override;
    void receive(std::span<const std::uint8_t> bytes, std::vector<TxChunk>& tx) override;
    double time_s() const override;
    std::uint64_t conversions() const override { return conversions_; }

private:
    void drain_tx(std::vector<TxChunk>& tx);

    fw::NativeBoard board_;  // first: the firmware's HAL calls need it
    fw::Firmware firmware_;
    DieTemperature die_;
    std::uint64_t conversions_ = 0;
};

}  // namespace driftlab::sim
