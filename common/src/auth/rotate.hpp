// Rotations the MAC candidates share (one definition, as the unity build joins their sources).
#pragma once

#include <stdint.h>

namespace driftlab {
namespace auth {

inline uint32_t rotr32(uint32_t x, unsigned n) { return (x >> n) | (x << (32U - n)); }

}  // namespace auth
}  // namespace driftlab
