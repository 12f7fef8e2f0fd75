// A/D counts <-> physical units, in one place (the paper's reading, DIGEST "Reading of the units").
// Counts stay the primary data; these scales turn fitted counts into the units of Table 1.
#pragma once

#include "driftlab/channels.hpp"

namespace driftlab::host {

/// Gyro: 90 deg/s over 512 counts (ENV-05S range on a 10-bit converter) [deg/s per count].
inline constexpr double kGyroDpsPerCount = 90.0 / 512.0;
/// Accelerometer: one count = 19.14 mm/s^2 = 1/512 g (ADXL05 through its amplifier, +-1 g over the converter, as the
/// simulator's span) [mm/s^2 per count]. Table 1 prints these very numbers under "cm/s^2"; read so, a count would be
/// 0.0195 g, ten times the simulator's, and +-10 g over the codes, twice the ADXL05's range (docs/sim.md §2).
inline constexpr double kAccelMmps2PerCount = 19.14;

/// Said under every accelerometer value printed in mm/s^2 (fit, report), since the paper's table says cm/s^2.
inline constexpr const char* kAccelScaleNote =
    "accelerometer values in mm/s^2 at 19.14 mm/s^2 (1/512 g) per count: the numbers of the paper's Table 1, whose "
    "column says cm/s^2 (ten times the +-1 g span the paper describes; docs/sim.md section 2)";

/// A channel's physical unit: the scale per count and the unit's name.
struct PhysicalUnit {
    double per_count;
    const char* name;
};

/// deg/s for the gyro, mm/s^2 for the accelerometer axes (Table 1's numbers).
constexpr PhysicalUnit physical_unit(Channel c) {
    return c == Channel::gyro ? PhysicalUnit{kGyroDpsPerCount, "deg/s"} : PhysicalUnit{kAccelMmps2PerCount, "mm/s^2"};
}

/// A difference of counts (e.g. C1, a standard error) in the physical unit.
constexpr double counts_to_physical(Channel c, double delta_counts) {
    return delta_counts * physical_unit(c).per_count;
}

/// A level in counts (e.g. C2) as its offset from the ideal at-rest code 512, in the physical unit. The paper
/// prints the magnitude (C2 = 505 -> 1.223 deg/s); this keeps the sign (-1.23 deg/s: below mid-scale).
constexpr double level_to_physical(Channel c, double level_counts) {
    return (level_counts - static_cast<double>(kMidScaleCode)) * physical_unit(c).per_count;
}

}  // namespace driftlab::host
