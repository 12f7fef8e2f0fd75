// Command authentication (docs/security.md, docs/protocol.md §3.14): a command that changes the board (CONFIG_SET,
// CAL_SET, KEY_SET) ends in a 12-byte trailer, a u32 counter and an 8-byte SipHash-2-4 tag under the board's key over
// the frame from its version byte through the counter. The board admits it when the tag verifies and the counter is
// above the last one admitted, which it keeps in EEPROM; so a forged command fails the tag and a replayed or reordered
// one the counter. The frame's CRC still covers the whole payload, tag included.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "driftlab/auth/siphash.hpp"
#include "driftlab/proto/nodiscard.hpp"

namespace driftlab {
namespace proto {

constexpr uint8_t kAuthCounterBytes = 4;
constexpr uint8_t kAuthTagBytes = 8;
/// Bytes an authenticated type adds to its fields [bytes].
constexpr uint8_t kAuthTrailerBytes = kAuthCounterBytes + kAuthTagBytes;
/// KEY_SET's field: the new key, sealed under the old one (seal_key).
constexpr uint8_t kKeySetFieldBytes = auth::kKeyBytes;

using Key = uint8_t[auth::kKeyBytes];

/// What a sender puts on a command: the board's key (nullptr for an open board, which ignores the tag: it is sent as
/// zeros) and a counter above the last one the board admitted.
struct CommandAuth {
  const Key* key;
  uint32_t counter;
};

/// True for the types that carry the trailer: CONFIG_SET, CAL_SET, KEY_SET.
DRIFTLAB_NODISCARD bool is_authenticated(uint8_t type_id);

/// Writes the trailer's counter and tag into `frame`, whose header and fields are written; its length byte says where
/// the trailer lies. The CRC is written after.
void write_trailer(uint8_t* frame, const CommandAuth& auth);

/// The counter of the trailer of the authenticated `frame` (header at frame[0], payload of its length byte).
DRIFTLAB_NODISCARD uint32_t trailer_counter(const uint8_t* frame);

/// True when the trailer's tag of `frame` is the one `key` gives (compared in time independent of where it differs).
DRIFTLAB_NODISCARD bool trailer_tag_matches(const uint8_t* frame, const Key& key);

/// KEY_SET's sealing of a new key: XOR with a keystream of SipHash-2-4 under the old `key` of (counter, block), so a
/// listener learns nothing of the new key and a counter never seals twice. Its own inverse: it also unseals.
void seal_key(const Key& key, uint32_t counter, const uint8_t* in, uint8_t* out);

}  // namespace proto
}  // namespace driftlab
