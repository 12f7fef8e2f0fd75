// The unit riding a robot: a planar, no-slip trajectory the sensor chain reads its true input from, and the ground
// truth written beside a log. Body frame as the paper mounts the unit: x forward, y left, z up; yaw counter-clockwise
// positive. A trajectory is a profile of segments, each with a linear speed and a linear yaw rate, so the sensors'
// inputs are exact at every instant: yaw rate ω, forward specific force dv/dt, lateral specific force v·ω (the
// centripetal acceleration), and gravity on z (the model's own at-rest input). docs/sim.md §Motion.
#pragma once

#include <cstddef>
#include <vector>

namespace driftlab::sim {

/// Standard gravity [m/s² per g] (ISO 80000-3).
inline constexpr double kStandardGravity = 9.80665;

/// One stretch of a profile: speed and yaw rate each change linearly over it.
struct ProfileSegment {
    double duration_s = 0.0;
    double speed_mps = 0.0;       ///< forward speed at the segment's start [m/s]
    double accel_mps2 = 0.0;      ///< its rate of change over the segment [m/s²]
    double yaw_rate_dps = 0.0;    ///< yaw rate at the segment's start [deg/s], counter-clockwise positive
    double yaw_accel_dps2 = 0.0;  ///< its rate of change [deg/s²]
};

/// What the sensors feel at an instant, beyond the at-rest input: yaw rate and horizontal specific force.
struct MotionInput {
    double yaw_rate_dps = 0.0;
    double accel_x_g = 0.0;  ///< forward
    double accel_y_g = 0.0;  ///< left
};

/// The ground truth at an instant: pose in the start frame and what the sensors feel.
struct MotionState {
    double x_m = 0.0;
    double y_m = 0.0;
    double heading_deg = 0.0;  ///< from the start frame's x axis, counter-clockwise, unwrapped
    double speed_mps = 0.0;
    MotionInput input;
};

class Trajectory {
public:
    /// At rest for `rest_before_s` [s of the board's clock], then `segments` one after the other; after the last
    /// one the unit keeps its final speed and yaw rate. An empty profile is a unit at rest throughout.
    Trajectory(std::vector<ProfileSegment> segments, double rest_before_s = 0.0);

    /// What the sensors feel at `t_s` [s of the board's clock]; cheap (the chain asks at every conversion).
    MotionInput input_at(double t_s) const;
    /// The whole truth at `t_s`: the pose integrated along the profile.
    MotionState state_at(double t_s) const;
    /// Whether the unit ever moves.
    bool moves() const;
    /// The instant the profile's last segment ends [s of the board's clock].
    double end_s() const { return starts_.empty() ? rest_before_s_ : starts_.back().t_s + segments_.back().duration_s; }

private:
    struct Start {  // the state where a segment begins
        double t_s, x_m, y_m, heading_deg;
    };
    /// The segment holding `t_s` (or the final hold, index segments_.size()) and the time into it.
    std::size_t locate(double t_s, double& into_s) const;
    MotionState advance(const Start& start, const ProfileSegment& seg, double into_s) const;

    std::vector<ProfileSegment> segments_;  // each at most kMaxSegmentS long, so integrating within one is short
    std::vector<Start> starts_;
    ProfileSegment hold_;  // after the last segment: its end speed and yaw rate, unchanging
    Start hold_start_{};
    double rest_before_s_;
};

}  // namespace driftlab::sim
