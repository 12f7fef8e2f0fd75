// KeyStore: the board's 128-bit command key in EEPROM with a CRC (docs/security.md): none (erased), valid, or damaged
// (the CRC fails: a board that cannot tell its key obeys no one until one is provisioned again).
#pragma once

#include <stdint.h>

#include "driftlab/auth/siphash.hpp"
#include "firmware/core/eeprom_record.hpp"

namespace driftlab {
namespace fw {

constexpr uint16_t kKeyEepromAddress = 96;
constexpr uint8_t kKeyRecordBytes = auth::kKeyBytes + kRecordCrcBytes;

enum class KeyState : uint8_t { none = 0, valid = 1, damaged = 2 };

class KeyStore {
 public:
  KeyStore() : key_(), state_(KeyState::none) {}

  /// Reads the key record (at boot).
  void load();
  /// Writes `key` with its CRC and takes it.
  void store(const uint8_t (&key)[auth::kKeyBytes]);

  KeyState state() const { return state_; }
  /// Meaningful when state() is valid.
  const uint8_t (&key() const)[auth::kKeyBytes] { return key_; }

  /// The record EEPROM holds for `key` (key bytes, then CRC-16/IBM-3740): what store() writes, for `driftlab flash
  /// --key` and an emulator's EEPROM image.
  static void record_bytes(const uint8_t (&key)[auth::kKeyBytes], uint8_t (&out)[kKeyRecordBytes]);

 private:
  uint8_t key_[auth::kKeyBytes];
  KeyState state_;
};

}  // namespace fw
}  // namespace driftlab
