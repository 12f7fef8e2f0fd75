// KeyStore record and its check (key_store.hpp).
#include "firmware/core/key_store.hpp"

#include "driftlab/proto/byte_order.hpp"
#include "driftlab/proto/crc16.hpp"
#include "firmware/core/hal.hpp"

namespace driftlab {
namespace fw {

void KeyStore::record_bytes(const uint8_t (&key)[auth::kKeyBytes], uint8_t (&out)[kKeyRecordBytes]) {
  for (uint8_t i = 0; i < auth::kKeyBytes; ++i) {
    out[i] = key[i];
  }
  proto::put_u16_le(out + auth::kKeyBytes, proto::crc16_ibm3740(key, auth::kKeyBytes));
}

void KeyStore::load() {
  uint8_t record[kKeyRecordBytes];
  hal_eeprom_read(kKeyEepromAddress, record, kKeyRecordBytes);
  uint8_t all = 0xFF;
  for (uint8_t i = 0; i < kKeyRecordBytes; ++i) {
    all = static_cast<uint8_t>(all & record[i]);
  }
  for (uint8_t i = 0; i < auth::kKeyBytes; ++i) {
    key_[i] = record[i];
  }
  if (all == 0xFF) {
    state_ = KeyState::none;
  } else if (proto::get_u16_le(record + auth::kKeyBytes) == proto::crc16_ibm3740(record, auth::kKeyBytes)) {
    state_ = KeyState::valid;
  } else {
    state_ = KeyState::damaged;
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
