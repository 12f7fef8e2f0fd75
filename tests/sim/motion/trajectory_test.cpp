// Trajectory (sim/motion/trajectory.hpp) against closed forms: a straight run under constant acceleration, a circle at
// constant speed and yaw rate, heading as the integral of the yaw rate, and what the sensors feel (dv/dt forward,
// v·ω to the left); the built-in trajectories against what docs/sim.md says of them.
#include "sim/motion/trajectory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/motion/trajectories.hpp"

namespace driftlab::sim {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Trajectory, AStraightRunUnderConstantAccelerationIsAParabola) {
    const Trajectory t({{4.0, 0.2, 0.5, 0.0, 0.0}}, 10.0);
    for (double into : {0.0, 0.7, 2.5, 3.9}) {
        const MotionState s = t.state_at(10.0 + into);
        EXPECT_NEAR(s.x_m, 0.2 * into + 0.25 * into * into, 1e-12) << into;
        EXPECT_NEAR(s.y_m, 0.0, 1e-12);
        EXPECT_NEAR(s.speed_mps, 0.2 + 0.5 * into, 1e-12);
        EXPECT_NEAR(s.input.accel_x_g, 0.5 / kStandardGravity, 1e-15);
        EXPECT_EQ(s.input.accel_y_g, 0.0);
    }
    // At rest before: nothing felt, nowhere gone.
    const MotionState before = t.state_at(9.99);
    EXPECT_EQ(before.x_m, 0.0);
    EXPECT_EQ(before.input.accel_x_g, 0.0);
    // After the profile the unit keeps its final speed (2.2 m/s) and moves on in a straight line.
    const MotionState after = t.state_at(16.0);
    EXPECT_NEAR(after.speed_mps, 2.2, 1e-12);
    EXPECT_NEAR(after.x_m, 0.2 * 4 + 0.25 * 16 + 2.2 * 2.0, 1e-12);
    EXPECT_EQ(after.input.accel_x_g, 0.0);
}

TEST(Trajectory, ConstantSpeedAndYawRateDrawACircleWithCentripetalForceToTheLeft) {
    const double v = 0.5, w_dps = 30.0, r = v / (w_dps * kPi / 180.0);
    const Trajectory t({{12.0, v, 0.0, w_dps, 0.0}});  // 360 degrees in 12 s
    for (double at : {0.0, 1.3, 6.0, 11.0}) {
        const MotionState s = t.state_at(at);
        const double h = w_dps * at * kPi / 180.0;
        EXPECT_NEAR(s.x_m, r * std::sin(h), 1e-12) << at;
        EXPECT_NEAR(s.y_m, r * (1.0 - std::cos(h)), 1e-12) << at;
        EXPECT_NEAR(s.heading_deg, w_dps * at, 1e-12);
        EXPECT_NEAR(s.input.accel_y_g, v * v / r / kStandardGravity, 1e-15);  // toward the centre, on the left
    }
    EXPECT_NEAR(t.state_at(12.0).x_m, 0.0, 1e-12);
}

// Where speed or yaw rate changes within a segment the pose is integrated (Simpson): checked against the closed form
// of a clothoid's first turn, heading = ω' t²/2 at constant speed, by a fine sum of the same integrand.
TEST(Trajectory, ThePoseUnderAChangingYawRateMatchesAFineIntegral) {
    const double v = 1.0, yaw_accel = 20.0;
    const Trajectory t({{3.0, v, 0.0, 0.0, yaw_accel}});
    double x = 0.0, y = 0.0;
    const int n = 3000000;
    for (int k = 0; k < n; ++k) {
        const double u = (k + 0.5) * 3.0 / n;
        const double h = 0.5 * yaw_accel * u * u * kPi / 180.0;
        x += v * std::cos(h) * 3.0 / n;
        y += v * std::sin(h) * 3.0 / n;
    }
    const MotionState s = t.state_at(3.0 - 1e-12);
    EXPECT_NEAR(s.x_m, x, 1e-9);
    EXPECT_NEAR(s.y_m, y, 1e-9);
    EXPECT_NEAR(s.heading_deg, 90.0, 1e-9);
    // The input the chain asks for at every conversion is the truth's.
    for (double at : {0.5, 1.5, 2.9}) {
        const MotionInput in = t.input_at(at);
        const MotionState full = t.state_at(at);
        EXPECT_DOUBLE_EQ(in.yaw_rate_dps, full.input.yaw_rate_dps);
        EXPECT_DOUBLE_EQ(in.accel_y_g, full.input.accel_y_g);
    }
}

TEST(Trajectory, ASquareClosesOnItselfWithFourLeftTurns) {
    const Trajectory t(builtin_profile("square", 40.0, 1));  // one lap: 4 x (5 s drive, 2 s, 2.5 s turn, 2 s)
    const double lap_s = 4 * (5.0 + 2.0 + 2.5 + 2.0);
    const MotionState s = t.state_at(lap_s);
    EXPECT_NEAR(s.x_m, 0.0, 1e-9);
    EXPECT_NEAR(s.y_m, 0.0, 1e-9);
    EXPECT_NEAR(s.heading_deg, 360.0, 1e-9);
    EXPECT_NEAR(t.state_at(5.0).x_m, 2.0, 1e-9);  // a 2 m side
    EXPECT_NEAR(t.state_at(5.0 + 2.0 + 2.5).heading_deg, 90.0, 1e-9);
    EXPECT_NEAR(t.state_at(7.0 + 1.25).input.yaw_rate_dps, 45.0, 1e-9);  // the turn's peak
}

TEST(Trajectory, EachFigureEightLobeTurnsAFullCircleAndTheTwoCancel) {
    const Trajectory t(builtin_profile("figure8", 100.0, 1));
    const double w = 0.5 * 180.0 / kPi, lobe_s = 1.0 + (360.0 / w - 1.0) + 1.0;
    EXPECT_NEAR(t.state_at(1.0 + lobe_s).heading_deg, 360.0, 1e-9);
    EXPECT_NEAR(t.state_at(1.0 + 2 * lobe_s).heading_deg, 0.0, 1e-9);
    EXPECT_NEAR(t.state_at(1.0 + lobe_s / 2).input.accel_y_g, 0.5 * 0.5 / kStandardGravity, 1e-12);
    EXPECT_NEAR(t.state_at(1.0 + 1.5 * lobe_s).input.accel_y_g, -0.5 * 0.5 / kStandardGravity, 1e-12);
}

TEST(Trajectory, TheTurntableHoldsEachRateTwentySecondsInPlace) {
    const Trajectory t(builtin_profile("turntable", 1.0, 1));
    // 10 s at rest, a 0.5 s ramp to 10 deg/s, 20 s held.
    EXPECT_EQ(t.state_at(5.0).input.yaw_rate_dps, 0.0);
    EXPECT_NEAR(t.state_at(20.0).input.yaw_rate_dps, 10.0, 1e-12);
    double largest = 0.0;
    for (double at = 0.0; at < t.end_s(); at += 0.25) {
        const MotionState s = t.state_at(at);
        largest = std::max(largest, std::abs(s.input.yaw_rate_dps));
        EXPECT_EQ(s.speed_mps, 0.0);
        EXPECT_EQ(s.input.accel_y_g, 0.0);
    }
    EXPECT_NEAR(largest, 80.0, 1e-12);
}

TEST(Trajectory, StopAndGoIsTheSameForASeedAndStaysWithinARobotsLimits) {
    const auto a = builtin_profile("stop-and-go", 600.0, 5), b = builtin_profile("stop-and-go", 600.0, 5),
               c = builtin_profile("stop-and-go", 600.0, 6);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(a.back().duration_s, b.back().duration_s);
    EXPECT_NE(a.size() == c.size() && a.back().duration_s == c.back().duration_s, true);
    const Trajectory t(a);
    EXPECT_GE(t.end_s(), 600.0);
    for (double at = 0.0; at < t.end_s(); at += 0.1) {
        const MotionState s = t.state_at(at);
        EXPECT_LE(s.speed_mps, 1.2 + 1e-12);
        EXPECT_GE(s.speed_mps, -1e-12);
        EXPECT_LE(std::abs(s.input.yaw_rate_dps), 60.0 + 1e-12);
    }
    EXPECT_EQ(t.state_at(t.end_s() + 10.0).speed_mps, 0.0) << "ends at rest";
}

TEST(Trajectory, RestIsNoMotionAndAnUnknownNameIsRefusedWithTheNames) {
    EXPECT_FALSE(Trajectory(builtin_profile("rest", 100.0, 1)).moves());
    EXPECT_TRUE(Trajectory(builtin_profile("square", 100.0, 1)).moves());
    try {
        make_trajectory("sqaure", 100.0, 0.0, 1);
        FAIL() << "an unknown name was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("rest, square, figure8, stop-and-go, turntable"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace driftlab::sim
