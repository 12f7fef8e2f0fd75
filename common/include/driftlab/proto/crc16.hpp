// CRC-16/IBM-3740 (a.k.a. CRC-16/CCITT-FALSE): width 16, poly 0x1021, init 0xFFFF, refin/refout false, xorout 0,
// check("123456789") = 0x29B1, per the CRC RevEng catalogue. Spec use: docs/protocol.md §2.
//
// Computed a byte at a time with the shift formula (no 512-byte table: the ATmega328P has 32 KiB of flash and the
// link runs at most a few kB/s).
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace driftlab {
namespace proto {

constexpr uint16_t kCrc16Ibm3740Init = 0xFFFF;
constexpr uint16_t kCrc16Ibm3740Check = 0x29B1;

/// Folds one byte into a running CRC-16/IBM-3740.
/// The formula is the polynomial division of 8 bits at once: with x = high byte ^ data and x ^= x >> 4,
/// the remainder is (crc << 8) ^ (x << 12) ^ (x << 5) ^ x for the generator x^16 + x^12 + x^5 + 1.
inline uint16_t crc16_ibm3740_update(uint16_t crc, uint8_t byte) {
  // Shift as unsigned: on AVR `int` is 16 bits, and a uint16_t would promote to it and shift into its sign bit.
  uint16_t x = static_cast<uint16_t>((crc >> 8) ^ byte);
  x = static_cast<uint16_t>(x ^ (x >> 4));
  const uint_fast16_t crc_u = crc;
  const uint_fast16_t x_u = x;
  return static_cast<uint16_t>((crc_u << 8) ^ (x_u << 12) ^ (x_u << 5) ^ x_u);
}

/// CRC-16/IBM-3740 of `size` bytes, continuing from `crc` (pass kCrc16Ibm3740Init to start).
uint16_t crc16_ibm3740(const uint8_t* data, size_t size, uint16_t crc = kCrc16Ibm3740Init);

}  // namespace proto
}  // namespace driftlab
