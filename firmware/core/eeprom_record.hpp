// EepromRecord: what the board keeps in EEPROM comes as records of data followed by their CRC-16/IBM-3740
// (little-endian), so that an erased record (every byte 0xFF) and a damaged one (a worn cell, a write cut by a reset)
// are told from a valid one: the calibration entries (cal_entry.hpp) and the command key (key_store.hpp).
#pragma once

#include <stdint.h>

namespace driftlab {
namespace fw {

constexpr uint8_t kRecordCrcBytes = 2;

enum class RecordState : uint8_t { valid, erased, damaged };

/// Writes the CRC of `record`'s first `data_bytes` bytes right after them.
void seal_record(uint8_t* record, uint8_t data_bytes);

/// What a record of `data_bytes` bytes and its CRC, as read from EEPROM, is.
RecordState record_state(const uint8_t* record, uint8_t data_bytes);

}  // namespace fw
}  // namespace driftlab
