/* Tags the ELF for simavr (avr_mcu_section.h): chip, clock and the 5 V board's VCC/AVCC/AREF [mV], so an emulator
 * needs no command-line options. The .mmcu section is not loaded into flash and not copied into the .hex. The
 * macros use C99 designated initializers, hence C. */
#include <avr/avr_mcu_section.h>

AVR_MCU(F_CPU, "atmega328p");
AVR_MCU_VOLTAGES(5000, 5000, 5000);
