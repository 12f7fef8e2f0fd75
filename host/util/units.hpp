// A/D counts <-> physical units, in one place (the paper's reading, DIGEST "Reading of the units").
// Counts stay the primary data; these scales turn fitted counts into the units of Table 1.
#pragma once

#include "driftlab/channels.hpp"

namespace driftlab::host {

/// Gyro: 90 deg/s over 512 counts (ENV-05S range on a 10-bit converter) [deg/s per count].
inline constexpr double kGyroDpsPerCount = 90.0 / 512.0;
/// Accelerometer: one count = 19.14 cm/s^2 (ADXL05 through its amplifier) [cm/s^2 per count].
inline constexpr double kAccelCmps2PerCount = 19.14;

/// Said under every accelerometer value printed in cm/s^2 (fit, report): the scale is the paper's Table 1 as printed,
/// 10x what the simulator's +-1 g span gives (1/512 g = 19.14 mm/s^2 per count), an open question (docs/sim.md §2).
/// accel_z's 2101 cm/s^2 from mid-scale at rest had read as 2.1 g without a word.
inline constexpr const char* kAccelScaleNote =
    "accelerometer values in cm/s^2 assume 19.14 cm/s^2 per count (0.0195 g), the paper's Table 1 as printed; the "
    "simulator's +-1 g span makes a count 1/512 g = 19.14 mm/s^2, 10x less (docs/sim.md section 2)";

/// A channel's physical unit: the scale per count and the unit's name.
struct PhysicalUnit {
    double per_count;
    const char* name;
};

/// deg/s for the gyro, cm/s^2 for the accelerometer axes (the units of Table 1).
constexpr PhysicalUnit physical_unit(Channel c) {
    return c == Channel::gyro ? PhysicalUnit{kGyroDpsPerCount, "deg/s"} : PhysicalUnit{kAccelCmps2PerCount, "cm/s^2"};
}

/// A difference of counts (e.g. C1, a standard error) in the physical unit.
constexpr double counts_to_physical(Channel c, double delta_counts) { return delta_counts * physical_unit(c).per_count; }

/// A level in counts (e.g. C2) as its offset from the ideal at-rest code 512, in the physical unit. The paper
/// prints the magnitude (C2 = 505 -> 1.223 deg/s); this keeps the sign (-1.23 deg/s: below mid-scale).
constexpr double level_to_physical(Channel c, double level_counts) {
    return (level_counts - static_cast<double>(kMidScaleCode)) * physical_unit(c).per_count;
}

}  // namespace driftlab::host
