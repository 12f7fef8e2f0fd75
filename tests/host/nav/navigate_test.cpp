// Planar navigation (host/nav) against closed forms: with exact readings every variant follows the trajectory the
// simulator integrates on its own; a constant gyro bias the initial rest sees is removed, one that starts after it
// turns the raw heading as b t; eq. 1 drift alone is removed by the forward correction to what its fit leaves, and
// left in by raw as the integral of eq. 1 less its initial mean. The filter's Jacobian against finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "host/nav/input_correction.hpp"
#include "host/nav/nav_score.hpp"
#include "host/nav/navigate.hpp"
#include "host/nav/planar_ekf.hpp"
#include "sim/model/sim_model.hpp"
#include "sim/motion/trajectories.hpp"

namespace driftlab::host::nav {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;
const sim::SimModel kUnit = sim::paper_model();

// Each axis's counts beside the motion's: a function of time since power-on [counts].
using Extra = std::function<double(std::size_t axis, double t_s)>;

struct Synthetic {
    LogData log;
    TruthFile truth;
    std::vector<std::size_t> rows;
    NavTruth nav_truth() const { return {truth, rows}; }
};

// Exact readings of `trajectory` every `period_s` from 0 to `duration_s`, at mid-scale plus `extra`.
Synthetic synthetic(const sim::Trajectory& trajectory, double duration_s, double period_s, const Extra& extra) {
    Synthetic s;
    s.log.source_name = "synthetic.csv";
    s.truth.path = "synthetic.truth.csv";
    const auto cps = counts_per_si(kUnit);
    for (std::size_t i = 0; i * period_s <= duration_s + 1e-9; ++i) {
        const double t = static_cast<double>(i) * period_s;
        const sim::MotionState m = trajectory.state_at(t);
        const std::array<double, 3> si = {m.input.yaw_rate_dps * kRadPerDeg, m.input.accel_x_g * sim::kStandardGravity,
                                          m.input.accel_y_g * sim::kStandardGravity};
        s.log.t_s.push_back(t);
        s.log.seq.push_back(i);
        for (std::size_t k = 0; k < kNavAxes; ++k)
            s.log.counts[channel_index(kNavChannels[k])].push_back(512.0 + cps[k] * si[k] + extra(k, t));
        s.log.counts[channel_index(Channel::accel_z)].push_back(600.0);
        s.truth.t_s.push_back(t);
        s.truth.x_m.push_back(m.x_m);
        s.truth.y_m.push_back(m.y_m);
        s.truth.heading_deg.push_back(m.heading_deg);
        s.truth.speed_mps.push_back(m.speed_mps);
        s.rows.push_back(i);
    }
    return s;
}

UnitDrift drift_of(const std::array<fit::DriftParameters, kNavAxes>& p, double white_density) {
    UnitDrift u;
    for (std::size_t k = 0; k < kNavAxes; ++k) {
        u.axes[k].drift = p[k];
        u.axes[k].white_density = white_density;
    }
    return u;
}

const Track& track(const NavRun& run, const std::string& name) {
    for (const Track& t : run.tracks)
        if (t.name == name) return t;
    throw std::runtime_error("no variant " + name);
}

// The steps are trapezoidal: exact on the heading (its rate is piecewise linear), and on the position converging as
// the step at least (the specific force steps where a segment starts, which no sampler places inside its step: first
// order there, second elsewhere).
TEST(Nav, ExactReadingsReproduceTheTrajectoryInEveryVariantConvergingWithTheStep) {
    const sim::Trajectory fig8 = sim::make_trajectory("figure8", 300.0, 10.0, 1);
    const UnitDrift flat = drift_of({{{0.0, 512.0, 100.0}, {0.0, 512.0, 100.0}, {0.0, 512.0, 100.0}}}, 1e-6);
    std::array<std::array<double, 4>, 2> error{};
    for (std::size_t step = 0; step < 2; ++step) {
        const Synthetic s = synthetic(fig8, 300.0, step == 0 ? 0.02 : 0.01, [](std::size_t, double) { return 0.0; });
        const NavRun run = navigate(s.log, kUnit, flat, s.nav_truth(), NavOptions{});
        ASSERT_EQ(run.tracks.size(), 4u);
        const std::size_t last = s.log.size() - 1;
        for (std::size_t v = 0; v < 4; ++v) {
            const Track& t = run.tracks[v];
            SCOPED_TRACE(t.name);
            EXPECT_NEAR(t.heading_deg[last], s.truth.heading_deg[last], 1e-6);
            error[step][v] = std::hypot(t.x_m[last] - s.truth.x_m[last], t.y_m[last] - s.truth.y_m[last]);
        }
    }
    for (std::size_t v = 0; v < 4; ++v) {
        EXPECT_LT(error[1][v], 1e-2) << v;  // over about 145 m
        EXPECT_GT(error[0][v] / error[1][v], 1.8) << v;
    }
}

TEST(Nav, AConstantGyroBiasIsRemovedByRawAndOneStartingAfterTheRestTurnsItAsBTimesT) {
    const sim::Trajectory rest = sim::make_trajectory("rest", 600.0, 0.0, 1);
    const auto cps = counts_per_si(kUnit);
    constexpr double kBiasDps = 0.2;
    const double b = kBiasDps * kRadPerDeg * cps[0];  // [counts]
    NavOptions o;
    o.rest_s = 10.0;
    const Synthetic always = synthetic(rest, 600.0, 0.1, [&](std::size_t k, double) { return k == 0 ? b : 0.0; });
    const NavRun a = navigate(always.log, kUnit, std::nullopt, always.nav_truth(), o);
    EXPECT_NEAR(track(a, "raw").heading_deg.back(), 0.0, 1e-9);

    const Synthetic later =
        synthetic(rest, 600.0, 0.1, [&](std::size_t k, double t) { return k == 0 && t > 20.05 ? b : 0.0; });
    const NavRun r = navigate(later.log, kUnit, std::nullopt, later.nav_truth(), o);
    const Track& raw = track(r, "raw");
    for (const double t : {60.0, 300.0, 600.0}) {
        const auto i = static_cast<std::size_t>(std::lround(t / 0.1));
        // From the row at 20.1 s; the trapezoid takes half of the step before it.
        EXPECT_NEAR(raw.heading_deg[i], kBiasDps * (t - 20.05), 1e-9) << t;
    }
}

// Eq. 1 alone on the gyro: raw leaves the integral of eq. 1 less its mean over the initial rest; forward leaves the
// integral of the difference between the truth and the model it is given.
TEST(Nav, Eq1DriftAloneIsLeftByRawAndRemovedByForwardToItsModelsOwnError) {
    const sim::Trajectory rest = sim::make_trajectory("rest", 1200.0, 0.0, 1);
    const fit::DriftParameters truth{3.0, 505.0, 411.0};   // Table 1's gyro
    const fit::DriftParameters model{2.9, 505.05, 400.0};  // a fit's error
    const auto cps = counts_per_si(kUnit);
    const Synthetic s = synthetic(
        rest, 1200.0, 0.1, [&](std::size_t k, double t) { return k == 0 ? fit::drift_model(truth, t) - 512.0 : 0.0; });
    UnitDrift u = drift_of({{model, {0.0, 512.0, 100.0}, {0.0, 512.0, 100.0}}}, 1e-6);
    const NavRun run = navigate(s.log, kUnit, u, s.nav_truth(), NavOptions{});
    // Independent quadrature (Simpson, 1 ms) of the closed forms.
    const auto integral = [](const std::function<double(double)>& f, double to) {
        const int n = static_cast<int>(to / 0.001);
        double sum = f(0.0) + f(to);
        for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(to * i / n);
        return sum * (to / n) / 3.0;
    };
    double rest_mean = 0.0;
    for (int i = 0; i < 100; ++i) rest_mean += fit::drift_model(truth, 0.1 * i) / 100.0;  // rows before 10 s
    const double deg_per_count_s = 1.0 / (cps[0] * kRadPerDeg);
    const double raw_expected =
        integral([&](double t) { return fit::drift_model(truth, t) - rest_mean; }, 1200.0) * deg_per_count_s;
    const double fwd_expected =
        integral([&](double t) { return fit::drift_model(truth, t) - fit::drift_model(model, t); }, 1200.0) *
        deg_per_count_s;
    EXPECT_NEAR(track(run, "raw").heading_deg.back(), raw_expected, 1e-6 * std::abs(raw_expected));
    EXPECT_NEAR(track(run, "forward").heading_deg.back(), fwd_expected, 1e-3);
    EXPECT_GT(std::abs(raw_expected), 50.0 * std::abs(fwd_expected));
}

// A gyro alone (a plain recording of one axis): the heading is navigated, zero-velocity updates read the gyro's bias
// and leave the accelerometers' (which read nothing) alone, and the NEES counts one degree of freedom.
TEST(Nav, AGyroAloneNavigatesTheHeadingAndItsStopsLearnTheBias) {
    const sim::Trajectory rest = sim::make_trajectory("rest", 600.0, 0.0, 1);
    const auto cps = counts_per_si(kUnit);
    std::mt19937_64 rng(7);
    std::normal_distribution<double> noise(0.0, 0.5);  // [counts]
    Synthetic s = synthetic(rest, 600.0, 0.1, [&](std::size_t k, double t) {
        return k == 0 ? 0.1 * kRadPerDeg * cps[0] * t / 60.0 + noise(rng) : 0.0;  // a bias rising 0.1 deg/s a minute
    });
    s.log.recorded[channel_index(Channel::accel_x)] = s.log.recorded[channel_index(Channel::accel_y)] = false;
    // The unit's model: no eq. 1, its white noise, and a bias that walks fast enough to follow the ramp.
    UnitDrift walks = drift_of({{{0.0, 512.0, 100.0}, {0.0, 512.0, 100.0}, {0.0, 512.0, 100.0}}}, 0.5 * std::sqrt(0.1));
    walks.axes[0].rate_random_walk = 0.05;
    walks.axes[1].present = walks.axes[2].present = false;
    NavOptions o;
    o.aid.zupt = true;
    const NavRun run = navigate(s.log, kUnit, walks, s.nav_truth(), o);
    EXPECT_TRUE(run.heading_only);
    const Track& raw = track(run, "raw");
    const Track& ekf = track(run, "ekf");
    ASSERT_TRUE(std::isfinite(ekf.heading_deg.back()));
    EXPECT_GT(ekf.zero_velocity_updates, 5000u);  // of 6000 rows
    EXPECT_LT(std::abs(ekf.heading_deg.back()) * 20.0, std::abs(raw.heading_deg.back()));
    EXPECT_EQ(ekf.x_m.back(), 0.0);
    EXPECT_EQ(score(run, s.nav_truth()).nees_dof, 1);
}

TEST(Nav, TheStrapdownsJacobianIsItsFiniteDifference) {
    PlanarEkf::State x0;
    x0 << 3.0, -2.0, 0.7, 0.4, -0.3, 0.01, 0.02, -0.03;
    const ImuReading a{0.3, 0.4, -0.2}, b{0.35, 0.1, 0.25};
    constexpr double dt = 0.05, h = 1e-6;
    const PlanarEkf::Covariance f = strapdown_jacobian(x0, dt, a, b);
    for (int j = 0; j < PlanarEkf::kStates; ++j) {
        const PlanarEkf::State e = h * PlanarEkf::State::Unit(j);
        const PlanarEkf::State numeric =
            (strapdown_step(x0 + e, dt, a, b) - strapdown_step(x0 - e, dt, a, b)) / (2 * h);
        for (int i = 0; i < PlanarEkf::kStates; ++i) EXPECT_NEAR(f(i, j), numeric(i), 1e-8) << i << "," << j;
    }
}

}  // namespace
}  // namespace driftlab::host::nav
