// A board's command key on the host: 128 bits from the system's random source, kept in a file only its owner may
// read, as ssh keeps its private keys (docs/security.md "Authenticated commands").
#pragma once

#include <string>

#include "sim/hil/board_key.hpp"

namespace driftlab::host::io {

using CommandKey = sim::BoardKey;

/// 16 bytes from getrandom(2). Throws DeviceError when the system has no randomness to give.
CommandKey new_key();

/// Writes `key` to `path` as 32 lower-case hex digits and a newline, created owner-only (0600) and never over an
/// existing file. Throws UsageError for an existing file, DeviceError when it cannot be written.
void write_key_file(const std::string& path, const CommandKey& key);

/// Reads a key file. Throws DataError naming the file when group or others may read or write it ("chmod 600"), or
/// when it is not 32 hex digits (and an optional newline).
CommandKey read_key_file(const std::string& path);

/// The board's key record (firmware/core/key_store.hpp) of the key in `key_path` as the Intel HEX avrdude writes into
/// EEPROM, in `key_path` + ".eeprom.hex", owner-only as the key; returns that path. Throws as read_key_file(), and
/// DeviceError when the image cannot be written.
std::string write_key_eeprom_image(const std::string& key_path);

}  // namespace driftlab::host::io
