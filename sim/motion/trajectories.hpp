// The trajectories `driftlab hil --trajectory NAME|FILE` takes: the built-in ones, and a profile file of the user's
// (profile_file.hpp). docs/sim.md §Motion.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sim/model/sensor_model.hpp"
#include "sim/motion/trajectory.hpp"

namespace driftlab::sim {

/// The built-in names, `rest` first (the unit on the table, as the paper's figures).
const std::vector<std::string>& trajectory_names();

/// The profile of built-in `name`, long enough to cover `duration_s` after the rest before it; `seed` draws
/// stop-and-go's stretches. Throws std::invalid_argument for an unknown name.
std::vector<ProfileSegment> builtin_profile(const std::string& name, double duration_s, std::uint64_t seed);

/// `name_or_file` as a built-in name, else as a profile file; at rest for `rest_before_s` first. Throws
/// std::invalid_argument for a name that is neither, ModelFileError (file and line) for a bad file.
Trajectory make_trajectory(const std::string& name_or_file, double duration_s, double rest_before_s,
                           std::uint64_t seed);

/// What `trajectory` adds to each channel's true input, for SensorModel::set_motion(): the yaw rate on the gyro,
/// the forward and lateral specific force on accel_x and accel_y; gravity on accel_z is the model's at-rest input.
SensorModel::MotionSource motion_source(std::shared_ptr<const Trajectory> trajectory);

}  // namespace driftlab::sim
