// CRC-16/IBM-3740 over a byte range (crc16.hpp).
#include "driftlab/proto/crc16.hpp"

namespace driftlab {
namespace proto {

uint16_t crc16_ibm3740(const uint8_t* data, size_t size, uint16_t crc) {
  for (size_t i = 0; i < size; ++i) {
    crc = crc16_ibm3740_update(crc, data[i]);
  }
  return crc;
}

}  // namespace proto
}  // namespace driftlab
