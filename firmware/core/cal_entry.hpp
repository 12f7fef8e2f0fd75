// CalEntry: where one channel's calibration entry lives in EEPROM and its bytes there (the CAL payload, then its
// CRC-16/IBM-3740: an EEPROM record, eeprom_record.hpp). Pure layout, no HAL: the firmware's store (cal_store.hpp) and
// an emulator's or programmer's EEPROM image (sim/hil/eeprom_image.hpp) share it.
#pragma once

#include <stdint.h>

#include "driftlab/proto/messages.hpp"
#include "firmware/core/eeprom_record.hpp"

namespace driftlab {
namespace fw {

/// Entry c at kCalEepromAddress + c x kCalEntryBytes.
constexpr uint16_t kCalEepromAddress = 0;
constexpr uint8_t kCalEntryBytes = proto::kCalPayloadSize + kRecordCrcBytes;

uint16_t entry_address(uint8_t channel);

/// The bytes EEPROM holds for `payload`'s entry.
void entry_bytes(const proto::CalPayload& payload, uint8_t (&out)[kCalEntryBytes]);

}  // namespace fw
}  // namespace driftlab
