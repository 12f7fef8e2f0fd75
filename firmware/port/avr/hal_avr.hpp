// Board bring-up of the ATmega328P port, called once by main_avr.cpp before Firmware::start() (docs/hal.md).
#pragma once

namespace driftlab {
namespace fw {

/// Records the reset cause, starts the watchdog, USART0 (115200 baud 8N1), the ADC (AVCC reference, prescaler
/// 128, auto-trigger from Timer1 compare match B) and idle sleep. Interrupts stay off; main enables them.
void avr_board_init();

/// Main loop: restarts the watchdog.
void avr_watchdog_kick();

}  // namespace fw
}  // namespace driftlab
