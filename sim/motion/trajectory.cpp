// A planar no-slip trajectory; see trajectory.hpp.
#include "sim/motion/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace driftlab::sim {
namespace {

// Segments are cut to at most this long, so the pose within one is integrated over a short span.
constexpr double kMaxSegmentS = 1.0;
// Simpson's rule steps per second where speed or yaw rate changes within a segment (closed form otherwise).
constexpr double kSimpsonStepsPerS = 200.0;

double radians(double deg) { return deg * std::numbers::pi / 180.0; }

}  // namespace

Trajectory::Trajectory(std::vector<ProfileSegment> segments, double rest_before_s) : rest_before_s_(rest_before_s) {
    if (!(rest_before_s >= 0.0) || !std::isfinite(rest_before_s))
        throw std::invalid_argument("trajectory: the rest before must be a finite time >= 0");
    for (const ProfileSegment& s : segments) {
        if (!(s.duration_s > 0.0) ||
            !std::isfinite(s.duration_s + s.speed_mps + s.accel_mps2 + s.yaw_rate_dps + s.yaw_accel_dps2))
            throw std::invalid_argument("trajectory: a segment needs a finite duration > 0 and finite rates");
        const int pieces = static_cast<int>(std::ceil(s.duration_s / kMaxSegmentS));
        const double piece_s = s.duration_s / pieces;
        for (int k = 0; k < pieces; ++k) {
            const double at = k * piece_s;
            segments_.push_back({piece_s, s.speed_mps + s.accel_mps2 * at, s.accel_mps2,
                                 s.yaw_rate_dps + s.yaw_accel_dps2 * at, s.yaw_accel_dps2});
        }
    }
    Start next{rest_before_s, 0.0, 0.0, 0.0};
    for (const ProfileSegment& seg : segments_) {
        starts_.push_back(next);
        const MotionState end = advance(next, seg, seg.duration_s);
        next = {next.t_s + seg.duration_s, end.x_m, end.y_m, end.heading_deg};
    }
    hold_start_ = next;
    if (!segments_.empty()) {
        const ProfileSegment& last = segments_.back();
        hold_.speed_mps = last.speed_mps + last.accel_mps2 * last.duration_s;
        hold_.yaw_rate_dps = last.yaw_rate_dps + last.yaw_accel_dps2 * last.duration_s;
    }
}

bool Trajectory::moves() const {
    return std::any_of(segments_.begin(), segments_.end(), [](const ProfileSegment& s) {
        return s.speed_mps != 0.0 || s.accel_mps2 != 0.0 || s.yaw_rate_dps != 0.0 || s.yaw_accel_dps2 != 0.0;
    });
}

std::size_t Trajectory::locate(double t_s, double& into_s) const {
    const auto after =
        std::upper_bound(starts_.begin(), starts_.end(), t_s, [](double t, const Start& s) { return t < s.t_s; });
    if (after == starts_.begin()) {  // still at rest before the profile
        into_s = 0.0;
        return segments_.size();
    }
    const auto k = static_cast<std::size_t>(after - starts_.begin()) - 1;
    into_s = t_s - starts_[k].t_s;
    if (into_s < segments_[k].duration_s) return k;
    into_s = t_s - hold_start_.t_s;
    return segments_.size();
}

MotionInput Trajectory::input_at(double t_s) const {
    double into = 0.0;
    const std::size_t k = locate(t_s, into);
    if (k == segments_.size() && t_s < hold_start_.t_s) return {};  // the rest before
    const ProfileSegment& seg = k < segments_.size() ? segments_[k] : hold_;
    const double v = seg.speed_mps + seg.accel_mps2 * into;
    const double w = seg.yaw_rate_dps + seg.yaw_accel_dps2 * into;
    return {w, seg.accel_mps2 / kStandardGravity, v * radians(w) / kStandardGravity};
}

MotionState Trajectory::state_at(double t_s) const {
    double into = 0.0;
    const std::size_t k = locate(t_s, into);
    if (k == segments_.size() && t_s < hold_start_.t_s) return {};
    return k < segments_.size() ? advance(starts_[k], segments_[k], into) : advance(hold_start_, hold_, into);
}

MotionState Trajectory::advance(const Start& start, const ProfileSegment& seg, double into_s) const {
    MotionState s;
    s.speed_mps = seg.speed_mps + seg.accel_mps2 * into_s;
    s.input.yaw_rate_dps = seg.yaw_rate_dps + seg.yaw_accel_dps2 * into_s;
    s.input.accel_x_g = seg.accel_mps2 / kStandardGravity;
    s.input.accel_y_g = s.speed_mps * radians(s.input.yaw_rate_dps) / kStandardGravity;
    s.heading_deg = start.heading_deg + seg.yaw_rate_dps * into_s + 0.5 * seg.yaw_accel_dps2 * into_s * into_s;
    const double h0 = radians(start.heading_deg), w = radians(seg.yaw_rate_dps);
    double dx = 0.0, dy = 0.0;
    if (seg.accel_mps2 == 0.0 && seg.yaw_accel_dps2 == 0.0) {
        // Constant speed and yaw rate: a straight line or a circular arc, exactly.
        if (w == 0.0) {
            dx = seg.speed_mps * into_s * std::cos(h0);
            dy = seg.speed_mps * into_s * std::sin(h0);
        } else {
            const double r = seg.speed_mps / w;
            dx = r * (std::sin(h0 + w * into_s) - std::sin(h0));
            dy = -r * (std::cos(h0 + w * into_s) - std::cos(h0));
        }
    } else {
        const int n = 2 * std::max(1, static_cast<int>(std::ceil(into_s * kSimpsonStepsPerS / 2.0)));
        const double h = into_s / n;
        for (int j = 0; j <= n; ++j) {
            const double u = j * h;
            const double weight = (j == 0 || j == n) ? 1.0 : (j % 2 == 1 ? 4.0 : 2.0);
            const double v = seg.speed_mps + seg.accel_mps2 * u;
            const double heading = h0 + radians(seg.yaw_rate_dps * u + 0.5 * seg.yaw_accel_dps2 * u * u);
            dx += weight * v * std::cos(heading);
            dy += weight * v * std::sin(heading);
        }
        dx *= h / 3.0;
        dy *= h / 3.0;
    }
    s.x_m = start.x_m + dx;
    s.y_m = start.y_m + dy;
    return s;
}

}  // namespace driftlab::sim
