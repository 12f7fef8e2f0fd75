// The ground truth written beside the log of a moving unit (`LOG.truth.csv`, docs/log-format.md §Ground truth): the
// trajectory at each of the log's rows, at its t_s (the board's clock, which the trajectory runs on).
#pragma once

#include <string>
#include <vector>

#include "sim/motion/trajectory.hpp"

namespace driftlab::sim {

/// Where the truth of the log at `log_path` goes: its name with `.csv` replaced by (or, without it, followed by)
/// `.truth.csv`.
std::string truth_path_for(const std::string& log_path);

/// The truth file's text: comment lines naming the trajectory and the rest before it, the header
/// `t_s,x_m,y_m,heading_deg,speed_mps,yaw_rate_dps,accel_x_g,accel_y_g,accel_z_g`, and a row at each of `rows_t_s`.
/// The accelerations are the specific force in the body frame, gravity's 1 g on z included.
std::string truth_table(const Trajectory& trajectory, const std::string& name, double rest_before_s,
                        const std::vector<double>& rows_t_s);

}  // namespace driftlab::sim
