// KeyStore: the board's 128-bit command key in EEPROM with a CRC (docs/security.md), as proto::AuthState: open
// (erased), keyed, or damaged (the CRC fails: a board that cannot tell its key obeys no one until one is provisioned
// again).
#pragma once

#include <stdint.h>

#include "driftlab/auth/siphash.hpp"
#include "driftlab/proto/messages.hpp"
#include "firmware/core/key_record.hpp"

namespace driftlab {
namespace fw {

class KeyStore {
 public:
  KeyStore() : key_(), state_(proto::AuthState::open) {}

  /// Reads the key record (at boot).
  void load();
  /// Writes `key` with its CRC and takes it.
  void store(const uint8_t (&key)[auth::kKeyBytes]);

  proto::AuthState state() const { return state_; }
  /// Meaningful when state() is keyed.
  const uint8_t (&key() const)[auth::kKeyBytes] { return key_; }

 private:
  uint8_t key_[auth::kKeyBytes];
  proto::AuthState state_;
};

}  // namespace fw
}  // namespace driftlab
