// The key record's bytes (key_record.hpp).
#include "firmware/core/key_record.hpp"

namespace driftlab {
namespace fw {

void key_record_bytes(const uint8_t (&key)[auth::kKeyBytes], uint8_t (&out)[kKeyRecordBytes]) {
  for (uint8_t i = 0; i < auth::kKeyBytes; ++i) {
    out[i] = key[i];
  }
  seal_record(out, auth::kKeyBytes);
}

}  // namespace fw
}  // namespace driftlab
