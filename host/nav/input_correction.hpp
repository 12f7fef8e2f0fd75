// What each variant subtracts from the unit's counts before navigating, and the counts' physical scale: a constant
// bias taken over the first seconds at rest (what a user without a model does), or eq. 1 sample by sample (the
// paper's forward correction). docs/nav.md §Variants.
#pragma once

#include <array>
#include <cstddef>
#include <optional>

#include "host/log/log_data.hpp"
#include "host/nav/planar_ekf.hpp"
#include "host/nav/unit_drift.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::host::nav {

/// Counts per SI unit of each navigation axis [counts per rad/s, per m/s^2]: the unit's front end and converter.
std::array<double, kNavAxes> counts_per_si(const sim::SimModel& unit);

/// The first seconds of a log, where the unit is known to stand: each axis's mean and standard deviation [counts].
struct InitialRest {
    double from_s = 0.0, to_s = 0.0;
    std::size_t rows = 0;
    std::array<double, kNavAxes> mean{}, sd{};
};

/// The rows of `log` up to `rest_s` seconds after its first. Throws DataError when fewer than 3 rows fall there.
InitialRest initial_rest(const LogData& log, double rest_s);

class InputCorrection {
public:
    /// A constant bias per axis: the initial rest's mean, known to its standard error.
    static InputCorrection constant(const InitialRest& rest);
    /// Eq. 1 per axis, known to its C2's standard error.
    static InputCorrection eq1(const UnitDrift& unit);

    /// What is subtracted from axis `k`'s counts at `t_s` seconds since power-on [counts].
    double counts(std::size_t k, double t_s) const;
    /// The standard deviation of the correction's error at the start [counts].
    const std::array<double, kNavAxes>& sd_counts() const { return sd_; }

private:
    std::array<double, kNavAxes> constant_{};
    std::optional<UnitDrift> drift_;
    std::array<double, kNavAxes> sd_{};
};

/// Row `i` of `log` as the unit read it, less `correction`, in SI units; 0 on an axis the log does not record.
ImuReading reading(const LogData& log, std::size_t i, const InputCorrection& correction,
                   const std::array<double, kNavAxes>& counts_per_si);

}  // namespace driftlab::host::nav
