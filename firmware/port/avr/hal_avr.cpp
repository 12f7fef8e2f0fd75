// The HAL on ATmega328P registers at 16 MHz (contract: firmware/core/hal.hpp, docs/hal.md "AVR port").
//  - Timer1 in CTC mode (TOP = OCR1A) at clk/64 = 250 kHz is the tick; OCR1B = OCR1A, so compare match B falls
//    on the period boundary and auto-triggers one ADC conversion per period.
//  - The ADC runs at 16 MHz / 128 = 125 kHz (inside the 50..200 kHz the datasheet asks for 10-bit accuracy)
//    against AVCC; its vector does the round-robin (isr_avr.cpp).
//  - USART0 runs at 115200 baud with U2X (UBRR 16, +2.1 %, the rate Arduino boards use).
#include "firmware/port/avr/hal_avr.hpp"
#include "firmware/core/critical.hpp"
#include "firmware/core/hal.hpp"
#include "firmware/core/version.hpp"
#include "firmware/port/avr/critical_avr.hpp"
#include "firmware/port/avr/isr_shared_avr.hpp"

#include <avr/eeprom.h>
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>
#include <avr/wdt.h>

namespace driftlab {
namespace fw {
namespace {

constexpr uint32_t kCpuHz = F_CPU;
constexpr uint32_t kTimer1Prescaler = 64;
static_assert(kCpuHz / kTimer1Prescaler == kTickHz, "Timer1 at clk/64 must tick at kTickHz");

constexpr uint32_t kBaud = 115200;
// U2X: the USART divides by 8; round to the nearest divisor.
constexpr uint16_t kUbrr = static_cast<uint16_t>((kCpuHz + 4U * kBaud) / (8U * kBaud) - 1U);
static_assert(kUbrr == 16, "115200 baud at 16 MHz with U2X is UBRR 16");

// ADMUX: AVCC reference (REFS0), right-adjusted result, mux input in the low bits.
constexpr uint8_t kAdmuxAvcc = _BV(REFS0);
// ADCSRA without ADSC: enabled, auto-trigger, interrupt, prescaler 128.
constexpr uint8_t kAdcsraRun = _BV(ADEN) | _BV(ADATE) | _BV(ADIE) | _BV(ADPS2) | _BV(ADPS1) | _BV(ADPS0);
// ADCSRB: ADTS = 101, Timer/Counter1 compare match B.
constexpr uint8_t kAdcsrbTimer1CompareB = _BV(ADTS2) | _BV(ADTS0);

constexpr uint16_t kAssertMagic = 0xA55A;

// Survive the watchdog reset that DRIFTLAB_ASSERT forces; only read when MCUSR says watchdog.
uint16_t g_assert_line_noinit __attribute__((section(".noinit")));
uint16_t g_assert_magic_noinit __attribute__((section(".noinit")));

ResetInfo g_reset_info;

// Time now [ticks]: the latest trigger tick plus TCNT1, corrected when the compare already happened but its
// vector has not run yet (interrupts off). Caller holds a CriticalSection.
uint32_t ticks_locked() {
  uint32_t tick = g_isr.trigger_tick;
  uint16_t count = TCNT1;
  if (TIFR1 & _BV(OCF1B)) {
    count = TCNT1;
    tick += g_isr.step_ticks;
  }
  return tick + count;
}

// One conversion started by hand with the ADC neither triggered nor interrupting (before the first hal_init()); its
// code.
uint16_t convert_by_hand() {
  ADCSRA = _BV(ADEN) | _BV(ADSC) | _BV(ADPS2) | _BV(ADPS1) | _BV(ADPS0);
  while (ADCSRA & _BV(ADSC)) {
  }
  return ADC;
}

}  // namespace

void avr_board_init() {
  const uint8_t mcusr = MCUSR;
  MCUSR = 0;
  wdt_disable();
  g_reset_info.cause = static_cast<uint8_t>(mcusr & (kResetPowerOn | kResetExternal | kResetBrownOut | kResetWatchdog));
  g_reset_info.assert_line = 0;
  if ((mcusr & kResetWatchdog) != 0 && g_assert_magic_noinit == kAssertMagic) {
    g_reset_info.assert_line = g_assert_line_noinit;
  }
  g_assert_magic_noinit = 0;

  UBRR0 = kUbrr;
  UCSR0A = _BV(U2X0);
  UCSR0C = _BV(UCSZ01) | _BV(UCSZ00);
  UCSR0B = _BV(RXEN0) | _BV(TXEN0) | _BV(RXCIE0);

  // Digital input buffers off on the analog pins (less current, less noise).
  uint8_t didr = 0;
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    didr = static_cast<uint8_t>(didr | _BV(kAdcPin[c]));
  }
  DIDR0 = didr;
  // The first conversion after enabling takes 25 ADC clocks instead of 13: spend it now, outside the schedule.
  ADMUX = static_cast<uint8_t>(kAdmuxAvcc | kAdcPin[0]);
  static_cast<void>(convert_by_hand());

  SMCR = 0;  // sleep mode idle (SM2..0 = 000): Timer1, ADC and USART keep running
  // The main loop wakes at least every conversion period (<= 262 ms); 1 s leaves room for an output burst.
  wdt_enable(WDTO_1S);
}

void avr_watchdog_kick() { wdt_reset(); }

void hal_init(const AdcSchedule& schedule) {
  CriticalSection lock;
  // Stop the tick first so that `now` is exact while the new cycle is set up.
  TCCR1B = 0;
  const uint32_t now = ticks_locked();
  // Stop triggering; let a conversion in progress finish so its result cannot land in the new schedule.
  ADCSRA = _BV(ADEN) | _BV(ADPS2) | _BV(ADPS1) | _BV(ADPS0);
  while (ADCSRA & _BV(ADSC)) {
  }
  ADCSRA = static_cast<uint8_t>(ADCSRA | _BV(ADIF));
  g_isr.adc_ring.clear();
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    g_isr.order[c] = schedule.order[c];
    g_isr.admux[c] = static_cast<uint8_t>(kAdmuxAvcc | kAdcPin[channel_index(schedule.order[c])]);
  }
  g_isr.slot = 0;
  g_isr.temperature = kTemperatureIdle;
  ADMUX = g_isr.admux[0];

  // The first cycle lasts until schedule.first_trigger_tick; the compare-B vector then sets the steady period.
  const uint32_t wait = arm_wait_ticks(schedule, now);
  g_isr.period_ticks = schedule.conversion_period_ticks;
  g_isr.trigger_tick = now;
  g_isr.step_ticks = wait;
  const uint16_t first_top = static_cast<uint16_t>(wait - 1U);
  TCCR1A = 0;
  TCNT1 = 0;
  OCR1A = first_top;
  OCR1B = first_top;
  TIFR1 = _BV(OCF1A) | _BV(OCF1B) | _BV(TOV1);
  TIMSK1 = _BV(OCIE1B);
  ADCSRB = kAdcsrbTimer1CompareB;
  ADCSRA = kAdcsraRun;
  TCCR1B = _BV(WGM12) | _BV(CS11) | _BV(CS10);
}

uint16_t hal_read_temperature() {
  ADMUX = kAdmuxTemperature;
  static_cast<void>(convert_by_hand());  // the first after switching the reference is thrown away
  const uint16_t code = convert_by_hand();
  ADMUX = static_cast<uint8_t>(kAdmuxAvcc | kAdcPin[0]);
  return code;
}

void hal_request_temperature() {
  // The vector leaves idle only on a request, so nothing can change the byte between this test and the write.
  if (g_isr.temperature == kTemperatureIdle) {
    g_isr.temperature = kTemperatureRequested;
  }
}

uint8_t hal_uart_write(const uint8_t* bytes, uint8_t count) {
  // Only this function produces into the TX ring, so the free space seen here can only grow meanwhile.
  if (g_isr.tx_ring.free_space() < count) {
    return 0;
  }
  for (uint8_t i = 0; i < count; ++i) {
    static_cast<void>(g_isr.tx_ring.push(bytes[i]));
  }
  CriticalSection lock;  // the UDRE vector clears UDRIE0 in the same register
  UCSR0B = static_cast<uint8_t>(UCSR0B | _BV(UDRIE0));
  return count;
}

uint32_t hal_ticks() {
  CriticalSection lock;
  return ticks_locked();
}

void hal_idle() {
  // Check and sleep with interrupts off; `sei` delays interrupts by one instruction, so a wake-up that arrives
  // after the check still ends the `sleep` that follows it.
  cli();
  if (g_isr.adc_ring.empty() && g_isr.rx_ring.empty()) {
    sleep_enable();
    sei();
    sleep_cpu();
    sleep_disable();
  }
  sei();
}

uint16_t hal_rx_overflow_count() {
  CriticalSection lock;
  return g_isr.rx_overflow_bytes;
}

ResetInfo hal_reset_info() { return g_reset_info; }

void hal_eeprom_read(uint16_t address, uint8_t* out, uint8_t count) {
  eeprom_read_block(out, reinterpret_cast<const void*>(address), count);
}

void hal_eeprom_write(uint16_t address, const uint8_t* bytes, uint8_t count) {
  eeprom_update_block(bytes, reinterpret_cast<void*>(address), count);
}

void hal_assert_failed(uint16_t line) {
  cli();
  g_assert_line_noinit = line;
  g_assert_magic_noinit = kAssertMagic;
  wdt_enable(WDTO_15MS);
  for (;;) {
  }
}

CriticalSection::CriticalSection() : saved_state_(interrupts_save_and_disable()) {}

CriticalSection::~CriticalSection() { interrupts_restore(saved_state_); }

}  // namespace fw
}  // namespace driftlab
