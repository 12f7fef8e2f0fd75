// A user's trajectory as a profile file: forward speed and yaw rate against time, linear between rows.
//
//   # a comment
//   t_s,speed_mps,yaw_rate_dps
//   0,0,0
//   2,1.0,0
//   ...
//
// Commas or blanks between fields; the header names the three columns, in any order. Times start at 0 and
// increase; after the last row the unit keeps that row's speed and yaw rate (end at 0, 0 to stop). docs/sim.md
// §Motion.
#pragma once

#include <string>
#include <vector>

#include "sim/motion/trajectory.hpp"

namespace driftlab::sim {

/// Beyond these no mobile robot goes, and both sensors are far past their range.
inline constexpr double kMaxProfileYawRateDps = 1000.0;
inline constexpr double kMaxProfileAccelG = 10.0;

/// The profile of the file at `path`. Throws ModelFileError naming the file and line: a missing or unreadable file,
/// a header without the three columns, a field that is no finite number, a time that does not increase, fewer than
/// two rows, a yaw rate or an acceleration (forward dv/dt, lateral v·ω) beyond the limits above.
std::vector<ProfileSegment> read_profile_file(const std::string& path);

}  // namespace driftlab::sim
