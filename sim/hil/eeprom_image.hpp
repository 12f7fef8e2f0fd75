// The board's EEPROM at power-on as an earlier `driftlab upload` left it: erased (0xFF) but for the calibration's
// entries where the firmware keeps them (firmware/core/cal_store.hpp). What `hil --cal` boots its board with, native,
// AVR in simavr or on a pseudo-terminal alike.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "driftlab/proto/messages.hpp"

namespace driftlab::sim {

/// fw::kEepromBytes bytes; empty `calibration`: all erased.
std::vector<std::uint8_t> eeprom_image(std::span<const proto::CalPayload> calibration);

}  // namespace driftlab::sim
