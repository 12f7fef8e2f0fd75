// Interrupt vectors of the ATmega328P port: move data between the peripherals and the rings, count what is
// lost, nothing else (docs/hal.md "AVR port"). All processing happens in the main loop.
#include <avr/interrupt.h>
#include <avr/io.h>

#include "firmware/port/avr/isr_shared_avr.hpp"

namespace driftlab {
namespace fw {

IsrShared g_isr;

}  // namespace fw
}  // namespace driftlab

using driftlab::fw::g_isr;

// Timer1 compare match B: the ADC has just been triggered. Running this vector clears OCF1B, which the ADC's
// auto-trigger needs as a fresh rising edge for the next period, and advances the trigger time. When the first
// cycle after arming had another length than the period, it sets the steady TOP; the counter has just been
// cleared, so the new TOP lies ahead of it. (Writing only on a change also spares emulators that restart the
// timer's phase on every OCR write.)
ISR(TIMER1_COMPB_vect) {
  const uint32_t step = g_isr.step_ticks;
  g_isr.trigger_tick = g_isr.trigger_tick + step;
  if (step != g_isr.period_ticks) {
    g_isr.step_ticks = g_isr.period_ticks;
    const uint16_t top = static_cast<uint16_t>(g_isr.period_ticks - 1U);
    OCR1A = top;
    OCR1B = top;
  }
}

// A conversion finished. The multiplexer change takes effect for the next trigger, which is at least
// kMinConversionPeriodTicks away, so the round-robin stays in step with the slots. After the round's last
// conversion a requested temperature is converted at once, twice (the first after switching the reference is thrown
// away), and queued between that conversion and the next trigger, which kMinTemperaturePeriodTicks leaves room for.
ISR(ADC_vect) {
  const uint16_t code_counts = ADC;
  const uint8_t temperature = g_isr.temperature;
  driftlab::fw::Conversion conversion;
  if (temperature >= driftlab::fw::kTemperatureDiscarding) {
    if (temperature == driftlab::fw::kTemperatureDiscarding) {
      g_isr.temperature = driftlab::fw::kTemperatureConverting;
      ADCSRA = static_cast<uint8_t>(ADCSRA | _BV(ADSC));
      return;
    }
    // Before the next trigger, so trigger_tick is still that of the round's last conversion.
    g_isr.temperature = driftlab::fw::kTemperatureIdle;
    ADMUX = g_isr.admux[0];
    conversion = {driftlab::fw::kTemperatureInput, code_counts, g_isr.trigger_tick};
  } else {
    const uint8_t slot = g_isr.slot;
    const uint8_t next = static_cast<uint8_t>(slot + 1U == driftlab::kChannelCount ? 0U : slot + 1U);
    g_isr.slot = next;
    conversion = {g_isr.order[slot], code_counts, g_isr.trigger_tick};
    if (next == 0U && temperature == driftlab::fw::kTemperatureRequested) {
      g_isr.temperature = driftlab::fw::kTemperatureDiscarding;
      ADMUX = driftlab::fw::kAdmuxTemperature;
      ADCSRA = static_cast<uint8_t>(ADCSRA | _BV(ADSC));
    } else {
      ADMUX = g_isr.admux[next];
    }
  }
  // A full ring loses this conversion; the core sees the tick gap and counts it.
  static_cast<void>(g_isr.adc_ring.push(conversion));
}

ISR(USART_RX_vect) {
  const uint8_t byte = UDR0;
  if (!g_isr.rx_ring.push(byte) && g_isr.rx_overflow_bytes != 0xFFFFU) {
    g_isr.rx_overflow_bytes = static_cast<uint16_t>(g_isr.rx_overflow_bytes + 1U);
  }
}

ISR(USART_UDRE_vect) {
  uint8_t byte = 0;
  if (g_isr.tx_ring.pop(&byte)) {
    UDR0 = byte;
  } else {
    UCSR0B = static_cast<uint8_t>(UCSR0B & ~_BV(UDRIE0));
  }
}
