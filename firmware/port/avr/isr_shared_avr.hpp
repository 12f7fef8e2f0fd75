// State the ATmega328P's interrupt handlers share with the main loop. Only rings (spsc_ring.hpp) and single
// bytes cross without a lock; multi-byte values are read inside a CriticalSection (docs/hal.md "AVR port").
// The simavr harness reads g_isr's trigger fields by offset (sim/avr/isr_shared_layout.hpp, checked against the
// ELF's symbol size): change the member order or types only together with that file.
#pragma once

#include <stdint.h>

#include "driftlab/channels.hpp"
#include "firmware/core/hal.hpp"
#include "firmware/core/spsc_ring.hpp"

namespace driftlab {
namespace fw {

struct IsrShared {
  SpscRing<Conversion, kAdcRingCapacity> adc_ring;  ///< ADC vector -> main loop
  SpscRing<uint8_t, kRxRingCapacity> rx_ring;       ///< USART RX vector -> main loop
  SpscRing<uint8_t, kTxRingCapacity> tx_ring;       ///< main loop -> USART UDRE vector
  volatile uint16_t rx_overflow_bytes;              ///< RX vector only; saturating [bytes]
  volatile uint32_t trigger_tick;                   ///< tick of the latest Timer1 compare match B = ADC trigger [ticks]
  volatile uint32_t step_ticks;                     ///< ticks from the latest trigger to the next: the first wait after
                                                    ///< arming, then period_ticks [ticks]
  uint16_t period_ticks;                            ///< armed conversion period [ticks]; written with interrupts off
  Channel order[kChannelCount];                     ///< channel of each conversion slot; written with interrupts off
  uint8_t admux[kChannelCount];                     ///< ADMUX value of each conversion slot (reference + mux input)
  volatile uint8_t slot;                            ///< ADC vector only: slot of the conversion in progress
  volatile uint8_t temperature;                     ///< TemperatureStep: main loop sets requested, the vector the rest
};

/// Where a die temperature conversion stands (hal_request_temperature()).
enum TemperatureStep : uint8_t {
  kTemperatureIdle = 0,
  kTemperatureRequested = 1,   ///< after the round's last conversion, convert
  kTemperatureDiscarding = 2,  ///< the first conversion after switching the reference, thrown away
  kTemperatureConverting = 3,  ///< the one queued
};

/// ADMUX of a die temperature conversion: internal 1.1 V reference (REFS1 | REFS0), input ADC8.
constexpr uint8_t kAdmuxTemperature = 0xC8;

extern IsrShared g_isr;

}  // namespace fw
}  // namespace driftlab
