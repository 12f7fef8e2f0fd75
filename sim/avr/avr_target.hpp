// AvrTarget: the host-in-the-loop's EmulatedBoard (sim/hil/emulated_board.hpp) backed by AvrBoard, so
// `driftlab hil --target avr` runs the real ELF with the same options, logs and JSON as the native target.
//
// Adapting the interface to the chip:
//  - Time 0 is the firmware's tick 0 (AvrBoard::firmware_epoch_cycle()), as on the native target; the 0.8 ms of
//    start-up code before it run in the constructor, where nothing can reach the board yet.
//  - The source is asked for a code at each conversion's trigger instant (its tick / kTickHz, the same double
//    the native target passes); the code becomes the millivolts that simavr converts back to it.
//  - UART output leaves byte by byte at the UART's rate; bytes are gathered into whole frames, each stamped with
//    the instant its first byte was written, because the HIL sends one link packet per frame.
//  - next_conversion_s() is the next trigger plus the conversion and interrupt time, so that when the HIL
//    advances there the firmware has taken the conversion.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "sim/avr/avr_board.hpp"
#include "sim/hil/emulated_board.hpp"

namespace driftlab::sim::avr {

class AvrTarget final : public EmulatedBoard {
public:
    /// Loads the ELF and runs it to its tick 0. Throws AvrError.
    explicit AvrTarget(const AvrBoardOptions& options);

    std::optional<double> next_conversion_s() const override;
    void advance_to(double t_s, ConversionSource& source, std::vector<TxChunk>& tx) override;
    void receive(std::span<const std::uint8_t> bytes, std::vector<TxChunk>& tx) override;
    double time_s() const override;
    std::uint64_t conversions() const override { return board_.triggered_conversions(); }

    const AvrBoard& board() const { return board_; }

private:
    void gather_frames(std::vector<TxChunk>& tx);
    double s_of_cycle(std::uint64_t cycle) const;

    ConversionSource* source_ = nullptr;  // set during advance_to(), the only time conversions happen
    AvrBoard board_;
    std::uint64_t epoch_cycle_ = 0;
    std::vector<UartTxByte> partial_;  // bytes of a frame still being sent
};

}  // namespace driftlab::sim::avr
