// CounterStore: a counter that only grows and survives resets and power cuts, kept in EEPROM over kCounterSlots
// slots in turn so that no cell wears out first: the replay counter of authenticated commands (docs/security.md).
//
// A slot holds the value and its complement (8 bytes); a slot whose halves disagree (erased, or a write cut by a
// reset) is no value. The counter is the largest valid slot; the next value goes to the slot after it. A value is
// written before the command it admits acts, so a command cut short by a reset is never admitted twice.
#pragma once

#include <stdint.h>

namespace driftlab {
namespace fw {

constexpr uint16_t kCounterEepromAddress = 128;
constexpr uint8_t kCounterSlots = 8;
constexpr uint8_t kCounterSlotBytes = 8;

class CounterStore {
 public:
  CounterStore() : value_(0), slot_(kCounterSlots - 1) {}

  /// Reads the slots (at boot): the largest valid value, 0 when none is.
  void load();
  /// The largest value written [commands].
  uint32_t value() const { return value_; }
  /// Writes `next` (> value()) to the slot after the current one. Precondition: next > value().
  void advance_to(uint32_t next);

 private:
  uint32_t value_;
  uint8_t slot_;  // where value_ lies
};

}  // namespace fw
}  // namespace driftlab
