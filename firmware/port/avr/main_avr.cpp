// ATmega328P entry point: bring the board up, start the firmware, then forever drain the interrupt rings into
// the core and sleep until the next interrupt (docs/hal.md §1 "The contract" for the events, §2 "AVR port" for
// the loop, sleep and watchdog).
#include <avr/interrupt.h>

#include "firmware/core/firmware.hpp"
#include "firmware/port/avr/hal_avr.hpp"
#include "firmware/port/avr/isr_shared_avr.hpp"

namespace {

driftlab::fw::Firmware g_firmware;

}  // namespace

int main() {
  using driftlab::fw::g_isr;
  driftlab::fw::avr_board_init();
  sei();
  g_firmware.start();
  for (;;) {
    driftlab::fw::avr_watchdog_kick();
    driftlab::fw::Conversion conversion = {};
    while (g_isr.adc_ring.pop(&conversion)) {
      g_firmware.on_conversion(conversion.channel, conversion.code_counts, conversion.tick);
    }
    uint8_t byte = 0;
    while (g_isr.rx_ring.pop(&byte)) {
      g_firmware.on_rx_byte(byte);
    }
    driftlab::fw::hal_idle();
  }
}
