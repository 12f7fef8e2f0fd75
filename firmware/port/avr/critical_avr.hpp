// InterruptLock: the ATmega328P's critical section as an inline scope guard: saves SREG, disables interrupts,
// restores SREG (and so the previous I flag) on exit, with compiler barriers so no access leaks out of the
// section. CriticalSection (firmware/core/critical.hpp) is defined with it in hal_avr.cpp; port code that runs
// often uses it directly to save the call.
#pragma once

#include <avr/io.h>
#include <stdint.h>

namespace driftlab {
namespace fw {

class InterruptLock {
 public:
  InterruptLock() : saved_sreg_(SREG) {
    __asm__ __volatile__("cli" ::: "memory");
  }
  ~InterruptLock() {
    __asm__ __volatile__("" ::: "memory");
    SREG = saved_sreg_;
  }
  InterruptLock(const InterruptLock&) = delete;
  InterruptLock& operator=(const InterruptLock&) = delete;

 private:
  uint8_t saved_sreg_;
};

}  // namespace fw
}  // namespace driftlab
