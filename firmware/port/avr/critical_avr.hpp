// The ATmega328P's critical section, behind CriticalSection (firmware/core/critical.hpp, defined in hal_avr.cpp):
// save SREG and disable interrupts; later restore SREG, and with it the previous I flag. The memory clobbers are
// compiler barriers, so no access to shared data moves out of the section.
#pragma once

#include <avr/io.h>
#include <stdint.h>

namespace driftlab {
namespace fw {

inline uint8_t interrupts_save_and_disable() {
  const uint8_t sreg = SREG;
  __asm__ __volatile__("cli" ::: "memory");
  return sreg;
}

inline void interrupts_restore(uint8_t sreg) {
  __asm__ __volatile__("" ::: "memory");
  SREG = sreg;
}

}  // namespace fw
}  // namespace driftlab
