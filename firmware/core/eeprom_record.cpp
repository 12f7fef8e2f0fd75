// EepromRecord: sealing and checking (eeprom_record.hpp).
#include "firmware/core/eeprom_record.hpp"

#include "driftlab/proto/byte_order.hpp"
#include "driftlab/proto/crc16.hpp"

namespace driftlab {
namespace fw {

void seal_record(uint8_t* record, uint8_t data_bytes) {
  proto::put_u16_le(record + data_bytes, proto::crc16_ibm3740(record, data_bytes));
}

RecordState record_state(const uint8_t* record, uint8_t data_bytes) {
  uint8_t all = 0xFF;
  for (uint8_t i = 0; i < data_bytes + kRecordCrcBytes; ++i) {
    all = static_cast<uint8_t>(all & record[i]);
  }
  if (all == 0xFF) {
    return RecordState::erased;
  }
  return proto::get_u16_le(record + data_bytes) == proto::crc16_ibm3740(record, data_bytes) ? RecordState::valid
                                                                                            : RecordState::damaged;
}

}  // namespace fw
}  // namespace driftlab
