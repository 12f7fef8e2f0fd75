// The board's EEPROM at power-on as `driftlab flash --key` and an earlier `driftlab upload` left it: erased (0xFF) but
// for the calibration's entries and the key record where the firmware keeps them (firmware/core/cal_store.hpp,
// key_store.hpp), its replay counter never advanced. What `hil --cal`/`--key` boot their board with, native, AVR in
// simavr or on a pseudo-terminal alike.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "driftlab/proto/messages.hpp"
#include "sim/hil/board_key.hpp"

namespace driftlab::sim {

/// fw::kEepromBytes bytes; empty `calibration` and no `key`: all erased.
std::vector<std::uint8_t> eeprom_image(std::span<const proto::CalPayload> calibration,
                                       const std::optional<BoardKey>& key = {});

}  // namespace driftlab::sim
