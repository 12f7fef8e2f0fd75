// What the firmware reports about itself and its board in VERSION (docs/protocol.md §3.2, docs/firmware.md).
// Both ports describe the same board, so native and AVR VERSION frames are identical.
#pragma once

#include <stdint.h>

#include "driftlab/channels.hpp"

namespace driftlab {
namespace fw {

constexpr uint8_t kFwMajor = 0;
constexpr uint8_t kFwMinor = 2;
constexpr uint8_t kFwPatch = 0;

/// Board variant: 1 = ATmega328P at 16 MHz (Arduino Uno/Nano), sensors on A0..A3 (docs/hardware.md).
constexpr uint8_t kBoardId = 1;
/// Converter resolution [bits] and reference (AVCC of a 5 V board) [mV].
constexpr uint8_t kAdcBits = 10;
constexpr uint16_t kVrefMv = 5000;

/// ADC multiplexer input of each channel, in Channel order: gyro A0, accel_x A1, accel_y A2, accel_z A3.
constexpr uint8_t kAdcPin[kChannelCount] = {0, 1, 2, 3};

}  // namespace fw
}  // namespace driftlab
