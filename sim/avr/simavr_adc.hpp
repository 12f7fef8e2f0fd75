// The inverse of simavr's ADC conversion, so that a code chosen by the sensor model comes out of the emulated
// ATmega328P unchanged. simavr 1.6 (avr_adc.c, ADCL read) converts an input of v [mV] against the reference
// vref [mV] as code = floor(v * 1023 / vref), clipped to 1023.
#pragma once

#include <cstdint>

namespace driftlab::sim::avr {

/// Reference of the 5 V board: AVCC = AREF = VCC [mV] (the firmware selects AVCC, hal_avr.cpp).
inline constexpr std::uint32_t kBoardVrefMv = 5000;

/// The internal reference the firmware converts the die temperature against (ADC8) [mV].
inline constexpr std::uint32_t kTemperatureVrefMv = 1100;

/// The smallest input [mV] that simavr converts to `code_counts` (0..1023) against `vref_mv`:
/// ceil(code * vref / 1023). One LSB is vref/1023 > 1 mV, so every code has such an integer input.
constexpr std::uint32_t millivolts_for_code(std::uint16_t code_counts, std::uint32_t vref_mv = kBoardVrefMv) {
    return (std::uint32_t{code_counts} * vref_mv + 1022U) / 1023U;
}

/// simavr's conversion itself, to check the inverse against.
constexpr std::uint16_t simavr_code_for_millivolts(std::uint32_t mv, std::uint32_t vref_mv = kBoardVrefMv) {
    const std::uint32_t code = mv * 1023U / vref_mv;
    return static_cast<std::uint16_t>(code > 1023U ? 1023U : code);
}

}  // namespace driftlab::sim::avr
