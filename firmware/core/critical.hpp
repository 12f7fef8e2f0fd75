// CriticalSection: scope guard that keeps interrupts away while main-loop code touches data an ISR also writes
// (multi-byte counters tear between byte reads on the AVR). Declared here, defined per port: SREG save, cli and
// restore on the ATmega328P (port/avr/critical_avr.hpp); nothing natively. Contract: docs/hal.md.
#pragma once

#include <stdint.h>

namespace driftlab {
namespace fw {

class CriticalSection {
 public:
  CriticalSection();
  ~CriticalSection();
  CriticalSection(const CriticalSection&) = delete;
  CriticalSection& operator=(const CriticalSection&) = delete;

 private:
  uint8_t saved_state_;  // the port's interrupt state on entry (SREG on the AVR)
};

}  // namespace fw
}  // namespace driftlab
