// The units a user may name for a gyro's or an accelerometer's samples, with their SI value: one table for every
// command that reads a plain recording (allan --unit, gap --as ...:UNIT), so that they accept the same spellings.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "host/stats/noise_terms.hpp"

namespace driftlab::host::stats {

struct RateUnit {
    std::string name;        ///< canonical spelling, for output (m/s^2 for m/s2)
    RateQuantity quantity;   ///< angular_rate or acceleration
    double si_per_unit;      ///< rad/s or m/s^2 per unit
};

/// The unit `name` stands for (deg/s, dps, mdps, deg/h, rad/s; g, mg, m/s^2, m/s2, cm/s^2,
/// cm/s2, mm/s^2, mm/s2: the physical units of host/util/units.hpp among them); none when unknown.
std::optional<RateUnit> rate_unit(std::string_view name);

/// The spellings rate_unit() knows for `quantity`, comma-separated, for a message.
std::string rate_unit_names(RateQuantity quantity);

/// Standard gravity [m/s^2 per g] (CGPM 1901), which g and mg stand for.
inline constexpr double kStandardGravity = 9.80665;

}  // namespace driftlab::host::stats
