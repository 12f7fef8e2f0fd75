// SipHash-2-4 (Aumasson and Bernstein, 2012): a 64-bit MAC under a 128-bit key, the board's command authenticator
// (docs/security.md "Authenticated commands" has the measurements that chose it). Freestanding C++14, no heap.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace driftlab {
namespace auth {

constexpr size_t kKeyBytes = 16;

/// SipHash-2-4 of `size` bytes under `key`, as the reference implementation returns it (little-endian u64).
uint64_t siphash24(const uint8_t (&key)[kKeyBytes], const uint8_t* data, size_t size);

}  // namespace auth
}  // namespace driftlab
