// BLAKE2s (RFC 7693) keyed, for short messages: a MAC candidate measured against SipHash-2-4 and truncated SHA-256
// (docs/security.md "Authenticated commands"). Freestanding C++14, no heap.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace driftlab {
namespace auth {

/// Keyed BLAKE2s of `size` bytes (any length) with a `key_size`-byte key (1..32), digest of `out_size` bytes (1..32).
void blake2s(const uint8_t* key, size_t key_size, const uint8_t* data, size_t size, uint8_t* out, size_t out_size);

}  // namespace auth
}  // namespace driftlab
