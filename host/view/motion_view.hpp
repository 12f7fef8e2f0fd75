// The view of a run in motion (`driftlab hil --trajectory ... --plot DIR`): the truth's yaw rate beside the gyro's
// reading of it, so that the lag, the scale factor and the rails show at a glance. docs/sim.md §Motion.
#pragma once

#include <string>
#include <vector>

namespace driftlab::host::view {

/// Renders DIR/hil_yaw_rate.png and .svg: `truth_dps` and `measured_dps` against `t_s` [s].
void write_yaw_rate_plot(const std::string& dir, const std::vector<double>& t_s, const std::vector<double>& truth_dps,
                         const std::vector<double>& measured_dps);

}  // namespace driftlab::host::view
