// The key record in EEPROM (docs/firmware.md, EEPROM layout): the 128-bit command key and its CRC at a fixed address.
// Pure bytes, no HAL: `driftlab flash --key` and an emulator's EEPROM image write the record the board reads
// (key_store.hpp).
#pragma once

#include <stdint.h>

#include "driftlab/auth/siphash.hpp"
#include "firmware/core/eeprom_record.hpp"

namespace driftlab {
namespace fw {

constexpr uint16_t kKeyEepromAddress = 96;
constexpr uint8_t kKeyRecordBytes = auth::kKeyBytes + kRecordCrcBytes;

/// The record EEPROM holds for `key`: key bytes, then CRC-16/IBM-3740 (eeprom_record.hpp).
void key_record_bytes(const uint8_t (&key)[auth::kKeyBytes], uint8_t (&out)[kKeyRecordBytes]);

}  // namespace fw
}  // namespace driftlab
