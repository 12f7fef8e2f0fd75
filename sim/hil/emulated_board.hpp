// EmulatedBoard: a firmware image running in virtual time, as the host-in-the-loop sees it. The native target
// (native_target.hpp: the firmware core on NativeBoard) implements it today; an AVR target (simavr running the
// real ELF) can implement the same three calls, so options, logs and JSON stay the same.
//
// How to drive it: call advance_to(t_s, source, tx) with non-decreasing times. The board runs every ADC
// conversion its firmware armed up to t_s, asking `source` for the code at each conversion's trigger instant,
// then stops at t_s; whatever the firmware wrote to its UART meanwhile is appended to `tx`, stamped with the
// instant it was written. receive() hands it bytes that arrived on its UART RX line at the current time.
// Times are seconds since the board's power-on (reset).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "driftlab/channels.hpp"

namespace driftlab::sim {

/// Where the board's ADC readings come from (the sensor model in a HIL run).
class ConversionSource {
public:
    virtual ~ConversionSource() = default;
    /// The 10-bit code of channel `c` for the conversion triggered at `t_s` [s since power-on].
    virtual std::uint16_t code(Channel c, double t_s) = 0;
};

/// Bytes the firmware wrote to its UART at one instant (a frame or a few).
struct TxChunk {
    double t_s;  ///< when the firmware wrote them [s since power-on]
    std::vector<std::uint8_t> bytes;
};

class EmulatedBoard {
public:
    virtual ~EmulatedBoard() = default;

    /// Trigger instant of the next conversion [s], or nothing while the firmware has not armed the ADC.
    virtual std::optional<double> next_conversion_s() const = 0;
    /// Runs the board up to `t_s` [s] (see the file comment); appends UART output to `tx`.
    virtual void advance_to(double t_s, ConversionSource& source, std::vector<TxChunk>& tx) = 0;
    /// Bytes arriving on UART RX now; the firmware's answers are appended to `tx`.
    virtual void receive(std::span<const std::uint8_t> bytes, std::vector<TxChunk>& tx) = 0;
    /// Current time [s since power-on].
    virtual double time_s() const = 0;
    /// Conversions the firmware has taken so far.
    virtual std::uint64_t conversions() const = 0;
};

}  // namespace driftlab::sim
