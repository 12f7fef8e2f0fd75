// KeyStore record and its check (key_store.hpp).
#include "firmware/core/key_store.hpp"

#include "firmware/core/hal.hpp"

namespace driftlab {
namespace fw {

void KeyStore::record_bytes(const uint8_t (&key)[auth::kKeyBytes], uint8_t (&out)[kKeyRecordBytes]) {
  for (uint8_t i = 0; i < auth::kKeyBytes; ++i) {
    out[i] = key[i];
  }
  seal_record(out, auth::kKeyBytes);
}

void KeyStore::load() {
  uint8_t record[kKeyRecordBytes];
  hal_eeprom_read(kKeyEepromAddress, record, kKeyRecordBytes);
  for (uint8_t i = 0; i < auth::kKeyBytes; ++i) {
    key_[i] = record[i];
  }
  switch (record_state(record, auth::kKeyBytes)) {
  case RecordState::erased: state_ = KeyState::none; break;
  case RecordState::valid: state_ = KeyState::valid; break;
  case RecordState::damaged: state_ = KeyState::damaged; break;
  }
}

void KeyStore::store(const uint8_t (&key)[auth::kKeyBytes]) {
  uint8_t record[kKeyRecordBytes];
  record_bytes(key, record);
  hal_eeprom_write(kKeyEepromAddress, record, kKeyRecordBytes);
  for (uint8_t i = 0; i < auth::kKeyBytes; ++i) {
    key_[i] = key[i];
  }
  state_ = KeyState::valid;
}

}  // namespace fw
}  // namespace driftlab
