// Intel HEX text for a few bytes at an address: what avrdude's `-U eeprom:w:FILE:i` takes to write the board's key
// record into its EEPROM (`driftlab flash --key`).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace driftlab::host::io {

/// Data records of at most 16 bytes each from `address` on, then the end-of-file record.
std::string intel_hex(std::uint16_t address, const std::vector<std::uint8_t>& bytes);

}  // namespace driftlab::host::io
