// Where the AVR firmware keeps the time of the ADC trigger in progress: the byte layout of fw::IsrShared
// (firmware/port/avr/isr_shared_avr.hpp) as avr-g++ lays it out (every type 1-byte aligned on the AVR).
//
// Why the harness reads it: the sensor model is evaluated at the firmware's own trigger tick, the tick the
// firmware stamps on the conversion and the native board passes to its code source, so both targets feed the
// model the same instants. At a Timer1 compare-B match (the trigger) the vector has not run yet, so the tick of
// the conversion starting is trigger_tick + step_ticks. The harness checks the total size against the ELF's
// g_isr symbol and refuses a firmware whose layout differs (AvrError), rather than read a wrong field.
#pragma once

#include <cstdint>

#include "firmware/core/hal.hpp"

namespace driftlab::sim::avr {

struct IsrSharedLayout {
    // SpscRing<T, N> = T slots[N], head u8, tail u8; Conversion = channel u8, code u16, tick u32.
    static constexpr std::uint32_t kConversionBytes = 1 + 2 + 4;
    static constexpr std::uint32_t kAdcRingBytes = fw::kAdcRingCapacity * kConversionBytes + 2;
    static constexpr std::uint32_t kRxRingBytes = fw::kRxRingCapacity + 2;
    static constexpr std::uint32_t kTxRingBytes = fw::kTxRingCapacity + 2;
    static constexpr std::uint32_t kRxOverflowOffset = kAdcRingBytes + kRxRingBytes + kTxRingBytes;
    static constexpr std::uint32_t kTriggerTickOffset = kRxOverflowOffset + 2;
    static constexpr std::uint32_t kStepTicksOffset = kTriggerTickOffset + 4;
    static constexpr std::uint32_t kPeriodTicksOffset = kStepTicksOffset + 4;
    static constexpr std::uint32_t kOrderOffset = kPeriodTicksOffset + 2;
    static constexpr std::uint32_t kAdmuxOffset = kOrderOffset + kChannelCount;
    static constexpr std::uint32_t kSlotOffset = kAdmuxOffset + kChannelCount;
    static constexpr std::uint32_t kTemperatureOffset = kSlotOffset + 1;
    static constexpr std::uint32_t kTotalBytes = kTemperatureOffset + 1;
};

/// The firmware's symbol for it (driftlab::fw::g_isr, mangled).
inline constexpr const char* kIsrSharedSymbol = "_ZN8driftlab2fw5g_isrE";

}  // namespace driftlab::sim::avr
