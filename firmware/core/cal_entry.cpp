// CalEntry layout (cal_entry.hpp).
#include "firmware/core/cal_entry.hpp"

#include "driftlab/proto/byte_order.hpp"
#include "driftlab/proto/crc16.hpp"

namespace driftlab {
namespace fw {

uint16_t entry_address(uint8_t channel) {
  return static_cast<uint16_t>(kCalEepromAddress + static_cast<uint16_t>(channel) * kCalEntryBytes);
}

void entry_bytes(const proto::CalPayload& payload, uint8_t (&out)[kCalEntryBytes]) {
  // The buffer holds the payload exactly, so `n` is its size.
  const size_t n = proto::serialize(payload, out, proto::kCalPayloadSize);
  proto::put_u16_le(out + proto::kCalPayloadSize, proto::crc16_ibm3740(out, n));
}

}  // namespace fw
}  // namespace driftlab
