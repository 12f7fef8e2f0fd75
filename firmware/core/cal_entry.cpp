// CalEntry layout (cal_entry.hpp).
#include "firmware/core/cal_entry.hpp"

namespace driftlab {
namespace fw {

uint16_t entry_address(uint8_t channel) {
  return static_cast<uint16_t>(kCalEepromAddress + static_cast<uint16_t>(channel) * kCalEntryBytes);
}

void entry_bytes(const proto::CalPayload& payload, uint8_t (&out)[kCalEntryBytes]) {
  // The buffer holds the payload exactly, so `n` is its size.
  const size_t n = proto::serialize(payload, out, proto::kCalPayloadSize);
  seal_record(out, static_cast<uint8_t>(n));
}

}  // namespace fw
}  // namespace driftlab
