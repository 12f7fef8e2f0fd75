// SHA-256 (FIPS 180-4), for the MAVLink-style MAC candidate: the first 6 bytes of SHA-256(key || message), as MAVLink 2
// signs its frames (docs/security.md "Authenticated commands"). Freestanding C++14, no heap.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace driftlab {
namespace auth {

/// SHA-256 of `a` (`a_size` bytes) followed by `b` (`b_size` bytes), into `out` (32 bytes).
void sha256(const uint8_t* a, size_t a_size, const uint8_t* b, size_t b_size, uint8_t (&out)[32]);

}  // namespace auth
}  // namespace driftlab
