// KeyStore record and its check (key_store.hpp).
#include "firmware/core/key_store.hpp"

#include "firmware/core/hal.hpp"

namespace driftlab {
namespace fw {

void KeyStore::load() {
  uint8_t record[kKeyRecordBytes];
  hal_eeprom_read(kKeyEepromAddress, record, kKeyRecordBytes);
  for (uint8_t i = 0; i < auth::kKeyBytes; ++i) {
    key_[i] = record[i];
  }
  switch (record_state(record, auth::kKeyBytes)) {
  case RecordState::erased: state_ = proto::AuthState::open; break;
  case RecordState::valid: state_ = proto::AuthState::keyed; break;
  case RecordState::damaged: state_ = proto::AuthState::damaged; break;
  }
}

void KeyStore::store(const uint8_t (&key)[auth::kKeyBytes]) {
  uint8_t record[kKeyRecordBytes];
  key_record_bytes(key, record);
  hal_eeprom_write(kKeyEepromAddress, record, kKeyRecordBytes);
  for (uint8_t i = 0; i < auth::kKeyBytes; ++i) {
    key_[i] = key[i];
  }
  state_ = proto::AuthState::keyed;
}

}  // namespace fw
}  // namespace driftlab
