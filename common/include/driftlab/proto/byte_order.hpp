// Little-endian field access for frames: every multi-byte field is written byte by byte, never by memcpy of a
// struct, so padding and host byte order cannot leak onto the wire (docs/protocol.md §1).
#pragma once

#include <stdint.h>

namespace driftlab {
namespace proto {

inline void put_u16_le(uint8_t* out, uint16_t v) {
  out[0] = static_cast<uint8_t>(v & 0xFFu);
  out[1] = static_cast<uint8_t>(v >> 8);
}

inline void put_u32_le(uint8_t* out, uint32_t v) {
  out[0] = static_cast<uint8_t>(v & 0xFFu);
  out[1] = static_cast<uint8_t>((v >> 8) & 0xFFu);
  out[2] = static_cast<uint8_t>((v >> 16) & 0xFFu);
  out[3] = static_cast<uint8_t>(v >> 24);
}

/// Two's complement on the wire; the conversion to unsigned is defined for every value.
inline void put_i32_le(uint8_t* out, int32_t v) { put_u32_le(out, static_cast<uint32_t>(v)); }

inline uint16_t get_u16_le(const uint8_t* in) {
  // Shift as unsigned: a uint8_t promotes to int, which is 16 bits on AVR.
  return static_cast<uint16_t>(static_cast<uint_fast16_t>(in[0]) | (static_cast<uint_fast16_t>(in[1]) << 8));
}

inline uint32_t get_u32_le(const uint8_t* in) {
  return static_cast<uint32_t>(in[0]) | (static_cast<uint32_t>(in[1]) << 8) | (static_cast<uint32_t>(in[2]) << 16) |
         (static_cast<uint32_t>(in[3]) << 24);
}

/// Inverse of put_i32_le without implementation-defined unsigned-to-signed conversion.
inline int32_t get_i32_le(const uint8_t* in) {
  const uint32_t u = get_u32_le(in);
  if (u <= 0x7FFFFFFFu) {
    return static_cast<int32_t>(u);
  }
  return -static_cast<int32_t>(~u) - 1;
}

}  // namespace proto
}  // namespace driftlab
