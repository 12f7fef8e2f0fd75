// What navigation knows of the unit before it moves: per axis it navigates with (the gyro, accel_x, accel_y), the
// turn-on drift of eq. 1 and the noise terms of its Allan deviation, from a rest recording of the same unit (`nav
// --fit-from`) or from what `fit --json` / `allan --json` printed (`nav --drift`). docs/nav.md §The unit's model.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "driftlab/channels.hpp"
#include "host/fit/drift_model.hpp"
#include "host/log/log_data.hpp"

namespace driftlab::host::nav {

/// The axes planar navigation reads, in this order: yaw rate, forward and lateral specific force.
inline constexpr std::size_t kNavAxes = 3;
inline constexpr std::array<Channel, kNavAxes> kNavChannels = {Channel::gyro, Channel::accel_x, Channel::accel_y};

/// One axis, in A/D counts and seconds.
struct AxisModel {
    fit::DriftParameters drift;    ///< eq. 1 [counts, s since power-on]
    double drift_sd_counts = 0.0;  ///< standard error of eq. 1's value at power-on (its C2) [counts]
    /// White noise density N (angle / velocity random walk) [counts sqrt(s)]: an output's variance is N^2 / period.
    double white_density = 0.0;
    double bias_instability = 0.0;        ///< B [counts]; 0 when not known or not resolved
    double bias_instability_tau_s = 0.0;  ///< the averaging time of the ADEV minimum, where B shows [s]
    double rate_random_walk = 0.0;        ///< K [counts / sqrt(s)]; 0 when not known or not resolved
    bool walks_known = false;             ///< B and K come from an Allan analysis (a fit file has neither)
    bool present = true;                  ///< false: the recording has no such channel (a gyro-only log: heading only)

    /// The bias random walk's power spectral density [counts^2 / s] the filter is driven with: K^2, plus the walk
    /// that reaches the flicker floor 0.664 B at the averaging time of the ADEV minimum, 3 (0.664 B)^2 / tau_B (a
    /// random walk's ADEV is K sqrt(tau / 3)); the flicker floor is a random walk's up to there and no further.
    double bias_walk_psd() const;
};

/// The random walk's power spectral density that reaches a flicker floor 0.664 B at the averaging time `tau_s` (a
/// random walk's ADEV is K sqrt(tau / 3)): how far bias instability B wanders up to there [unit^2 / s].
double flicker_walk_psd(double b, double tau_s);

struct UnitDrift {
    std::array<AxisModel, kNavAxes> axes;
    std::string source;              ///< where it came from, for the output
    std::vector<std::string> notes;  ///< what it lacks (no Allan terms in a fit file) and how that is handled
};

/// The model `fit --json` or `allan --json` printed (the channels gyro, accel_x and accel_y, in counts). Throws
/// DataError naming the file and what is missing: a channel, eq. 1's parameters, a noise level.
UnitDrift read_unit_drift(const std::string& path);

/// Eq. 1 and the Allan terms (of the drift-removed series) of each axis of a rest recording, rows with
/// from_s <= t_s <= to_s. Throws DataError naming the log where an axis cannot be fitted.
UnitDrift fit_unit_drift(const LogData& rest, double from_s, double to_s);

}  // namespace driftlab::host::nav
