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
/// the remainder is (crc << 8) ^ (x << 12) ^ (x << 5) ^ x for the generator x^16 + x^12 + x^5 + 1. It is written
/// on the two register halves so that an 8-bit CPU needs byte operations only (a third of the cycles of the
/// 16-bit form on the ATmega328P).
inline uint16_t crc16_ibm3740_update(uint16_t crc, uint8_t byte) {
  uint8_t x = static_cast<uint8_t>((crc >> 8) ^ byte);
  x = static_cast<uint8_t>(x ^ (x >> 4));
  const uint8_t low = static_cast<uint8_t>(crc & 0xFFu);
  // High half: low << 8, plus the bits of x << 12 and x << 5 that land above bit 7.
  const uint8_t new_high = static_cast<uint8_t>(low ^ static_cast<uint8_t>(x << 4) ^ static_cast<uint8_t>(x >> 3));
  const uint8_t new_low = static_cast<uint8_t>(static_cast<uint8_t>(x << 5) ^ x);
  // Shift as unsigned: on AVR `int` is 16 bits, and a uint8_t would promote to it and shift into its sign bit.
  return static_cast<uint16_t>((static_cast<uint_fast16_t>(new_high) << 8) | new_low);
}

/// CRC-16/IBM-3740 of `size` bytes, continuing from `crc` (pass kCrc16Ibm3740Init to start).
uint16_t crc16_ibm3740(const uint8_t* data, size_t size, uint16_t crc = kCrc16Ibm3740Init);

}  // namespace proto
}  // namespace driftlab
