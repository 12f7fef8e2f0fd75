// A navigation run scored against its truth, the figures readers of the field expect (docs/nav.md §Scores): heading
// and position error at fixed times, heading drift per minute, position error as a share of the distance travelled,
// and the filter's consistency (the share of epochs whose pose NEES lies inside its two-sided 95 % chi-square band).
#pragma once

#include <string>
#include <vector>

#include "host/nav/navigate.hpp"

namespace driftlab::host::nav {

/// The evaluation times [s after the log's first row]: 1, 5, 10 and 30 minutes.
inline const std::vector<double> kNavEvalTimesS = {60.0, 300.0, 600.0, 1800.0};

struct VariantScore {
    std::string name;
    std::vector<double> heading_error_deg;  ///< |estimate - truth| at each time; NaN past the log's end
    std::vector<double> position_error_m;   ///< the same for the position
    double final_heading_error_deg = 0.0, final_position_error_m = 0.0;  ///< at the last row
    double heading_drift_deg_per_min = 0.0;  ///< the last row's heading error over the run's minutes
    double position_error_pct = NAN;         ///< the last row's position error over the distance travelled; NaN at rest
    double nees_inside_fraction = NAN;       ///< of the epochs after the first
};

struct NavScore {
    std::vector<double> at_s;
    double duration_s = 0.0;
    double distance_m = 0.0;  ///< travelled, along the truth
    int nees_dof = 3;         ///< 1 for a run of the heading alone
    std::vector<VariantScore> variants;
};

/// The two-sided 95 % band of a NEES with `dof` degrees of freedom (3 for the pose, 1 for the heading alone).
struct NeesBand {
    double low, high;
};
NeesBand nees_band(int dof);

NavScore score(const NavRun& run, const NavTruth& truth, const std::vector<double>& at_s = kNavEvalTimesS);

/// What a run without a truth can say of a variant's drift: its heading change while it found the unit standing,
/// per minute stood [deg/min]; NaN without a stop.
double heading_drift_at_stops(const Track& track, const std::vector<double>& t_s);

}  // namespace driftlab::host::nav
