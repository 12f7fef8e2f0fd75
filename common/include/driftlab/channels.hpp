// The four channels of the IMU, in the order every frame, log column and JSON object uses.
// Nominal scales are the paper's reading (host/util/units.hpp, docs/hardware.md "Sensors and wiring"); A/D counts
// stay the primary data.
#pragma once

#include <stdint.h>

namespace driftlab {

/// Sensor channels: ENV-05S rate gyro and the three ADXL05 accelerometer axes.
enum class Channel : uint8_t { gyro = 0, accel_x = 1, accel_y = 2, accel_z = 3 };

constexpr uint8_t kChannelCount = 4;

/// Names used in logs, JSON and model files. Index with `channel_index()`.
constexpr const char* kChannelNames[kChannelCount] = {"gyro", "accel_x", "accel_y", "accel_z"};

constexpr uint8_t channel_index(Channel c) { return static_cast<uint8_t>(c); }

/// Ideal at-rest code of a 10-bit converter (mid-scale).
constexpr uint16_t kMidScaleCode = 512;

}  // namespace driftlab
