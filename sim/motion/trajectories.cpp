// The built-in trajectories; see trajectories.hpp. Speeds and rates are a small indoor robot's: 0.3-1.2 m/s,
// 0.5 m/s² to start and stop, turns in place well inside the gyro's ±90 deg/s.
#include "sim/motion/trajectories.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "sim/model/rng.hpp"
#include "sim/model/streams.hpp"
#include "sim/motion/profile_file.hpp"

namespace driftlab::sim {
namespace {

constexpr double kAccelMps2 = 0.5;  // starting and stopping

// Appends segments that keep speed and yaw rate continuous.
class ProfileBuilder {
public:
    double t_s() const { return t_s_; }
    std::vector<ProfileSegment> take() { return std::move(segments_); }

    /// Holds the present speed and yaw rate.
    void hold(double s) { add(s, 0.0, 0.0); }
    /// Changes the speed to `to` at kAccelMps2.
    void speed_to(double to) {
        if (to != v_) add(std::abs(to - v_) / kAccelMps2, to > v_ ? kAccelMps2 : -kAccelMps2, 0.0);
    }
    /// Changes the yaw rate to `to` linearly over `over_s`.
    void yaw_rate_to(double to, double over_s) { add(over_s, 0.0, (to - w_) / over_s); }
    /// Turns by `angle_deg` in place from rest: up to `peak_dps` in `ramp_s`, hold, down again.
    void turn(double angle_deg, double peak_dps, double ramp_s) {
        const double sign = angle_deg < 0.0 ? -1.0 : 1.0;
        yaw_rate_to(sign * peak_dps, ramp_s);
        const double hold_s = std::abs(angle_deg) / peak_dps - ramp_s;
        if (hold_s > 0.0) hold(hold_s);
        yaw_rate_to(0.0, ramp_s);
    }

private:
    void add(double s, double accel, double yaw_accel) {
        segments_.push_back({s, v_, accel, w_, yaw_accel});
        v_ += accel * s;
        w_ += yaw_accel * s;
        t_s_ += s;
    }
    std::vector<ProfileSegment> segments_;
    double v_ = 0.0, w_ = 0.0, t_s_ = 0.0;
};

// Drive a 2 m side, stop, turn 90 degrees left in place, stop; repeat.
void square(ProfileBuilder& b) {
    b.speed_to(0.5);
    b.hold(3.0);
    b.speed_to(0.0);
    b.hold(2.0);
    b.turn(90.0, 45.0, 0.5);
    b.hold(2.0);
}

// Two circles of 1 m radius at 0.5 m/s, the first to the left, the second to the right: each lobe's yaw rate rises
// in 1 s, holds and falls in 1 s, turning 360 degrees.
void figure8_lobes(ProfileBuilder& b) {
    const double w = 0.5 / 1.0 * 180.0 / std::numbers::pi;
    for (double sign : {1.0, -1.0}) {
        b.yaw_rate_to(sign * w, 1.0);
        b.hold(360.0 / w - 1.0);
        b.yaw_rate_to(0.0, 1.0);
    }
}

// Steps of constant rate, each held 20 s with 10 s at rest between, both senses, up to 80 deg/s.
void turntable(ProfileBuilder& b) {
    for (double rate : {10.0, 20.0, 40.0, 60.0, 80.0})
        for (double sign : {1.0, -1.0}) {
            b.hold(10.0);
            b.yaw_rate_to(sign * rate, rate / 20.0);
            b.hold(20.0);
            b.yaw_rate_to(0.0, rate / 20.0);
        }
}

// A delivery robot's stretch: a stop of 2-20 s, now and then a turn in place, a drive of 3-30 s at 0.3-1.2 m/s,
// half of them along a gentle curve.
void stop_and_go(ProfileBuilder& b, Rng& rng) {
    b.hold(2.0 + 18.0 * rng.uniform());
    if (rng.uniform() < 0.4) {
        b.turn(360.0 * rng.uniform() - 180.0, 60.0, 0.5);
        b.hold(1.0);
    }
    b.speed_to(0.3 + 0.9 * rng.uniform());
    const double curve = rng.uniform() < 0.5 ? 20.0 * rng.uniform() - 10.0 : 0.0;
    b.yaw_rate_to(curve, 0.5);
    b.hold(3.0 + 27.0 * rng.uniform());
    b.yaw_rate_to(0.0, 0.5);
    b.speed_to(0.0);
}

}  // namespace

const std::vector<std::string>& trajectory_names() {
    static const std::vector<std::string> names = {"rest", "square", "figure8", "stop-and-go", "turntable"};
    return names;
}

std::vector<ProfileSegment> builtin_profile(const std::string& name, double duration_s, std::uint64_t seed) {
    const auto& names = trajectory_names();
    if (std::find(names.begin(), names.end(), name) == names.end())
        throw std::invalid_argument("unknown trajectory '" + name + "'");
    ProfileBuilder b;
    Rng rng(seed, kTrajectoryStream);
    if (name == "rest") return {};
    if (name == "figure8") b.speed_to(0.5);
    while (b.t_s() < duration_s) {
        if (name == "square")
            square(b);
        else if (name == "figure8")
            figure8_lobes(b);
        else if (name == "turntable")
            turntable(b);
        else
            stop_and_go(b, rng);
    }
    if (name == "figure8") b.speed_to(0.0);
    return b.take();
}

SensorModel::MotionSource motion_source(std::shared_ptr<const Trajectory> trajectory) {
    return [trajectory = std::move(trajectory)](double board_t_s) {
        const MotionInput m = trajectory->input_at(board_t_s);
        ChannelValues v{};
        v[channel_index(Channel::gyro)] = m.yaw_rate_dps;
        v[channel_index(Channel::accel_x)] = m.accel_x_g;
        v[channel_index(Channel::accel_y)] = m.accel_y_g;
        return v;
    };
}

Trajectory make_trajectory(const std::string& name_or_file, double duration_s, double rest_before_s,
                           std::uint64_t seed) {
    for (const std::string& n : trajectory_names())
        if (n == name_or_file) return Trajectory(builtin_profile(n, duration_s, seed), rest_before_s);
    if (!std::filesystem::exists(name_or_file)) {
        std::string names;
        for (const std::string& n : trajectory_names()) names += (names.empty() ? "" : ", ") + n;
        throw std::invalid_argument("unknown trajectory '" + name_or_file + "': neither a built-in one (" + names +
                                    ") nor a profile file");
    }
    return Trajectory(read_profile_file(name_or_file), rest_before_s);
}

}  // namespace driftlab::sim
