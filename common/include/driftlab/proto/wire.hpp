// Frame layout of protocol v2 (the same as v1's): sync bytes, header offsets, sizes. Spec: docs/protocol.md §1.
//
//   off   size  field
//   0     1     sync0 = 0xD7
//   1     1     sync1 = 0x1A
//   2     1     version = 2
//   3     1     type (msg_table.hpp)
//   4     2     seq, u16 little-endian, +1 per frame sent by this sender, wraps
//   6     1     len = payload bytes, equal to the type's fixed length, <= 32
//   7     len   payload (messages.hpp), little-endian fields
//   7+len 2     crc, u16 little-endian: CRC-16/IBM-3740 over bytes 2..6+len, then the type's seed byte
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace driftlab {
namespace proto {

constexpr uint8_t kSync0 = 0xD7;
constexpr uint8_t kSync1 = 0x1A;
constexpr uint8_t kProtocolVersion = 2;

/// Protocol version 1, to which a board and a host give a clear answer (docs/protocol.md §1.1). Its HELLO is v2's (no
/// payload, the same seed); its VERSION is v2's first 20 bytes under another seed.
constexpr uint8_t kLegacyProtocolVersion = 1;
constexpr uint8_t kLegacyHelloSeed = 0x9F;
constexpr uint8_t kLegacyVersionSeed = 0x59;
constexpr uint8_t kLegacyVersionPayloadSize = 20;

constexpr size_t kOffsetSync0 = 0;
constexpr size_t kOffsetSync1 = 1;
constexpr size_t kOffsetVersion = 2;
constexpr size_t kOffsetType = 3;
constexpr size_t kOffsetSeq = 4;
constexpr size_t kOffsetLen = 6;
constexpr size_t kOffsetPayload = 7;

/// First byte covered by the CRC (sync bytes are not: they carry no information once matched).
constexpr size_t kCrcStart = kOffsetVersion;

constexpr size_t kHeaderSize = kOffsetPayload;
constexpr size_t kCrcSize = 2;
/// Bytes a frame adds to its payload [bytes].
constexpr size_t kFrameOverhead = kHeaderSize + kCrcSize;
/// Largest payload of any type [bytes]; the decoder's buffer holds exactly one frame of this size.
constexpr size_t kMaxPayload = 32;
constexpr size_t kMaxFrameSize = kMaxPayload + kFrameOverhead;

static_assert(kFrameOverhead == 9, "protocol v1 overhead is 9 bytes per frame");
static_assert(kMaxFrameSize <= 255, "frame offsets are held in uint8_t");

/// Size of a whole frame carrying `payload_len` payload bytes [bytes].
constexpr size_t frame_size(size_t payload_len) { return payload_len + kFrameOverhead; }

}  // namespace proto
}  // namespace driftlab
