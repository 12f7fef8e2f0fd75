// E13 clock_jitter: the drift in ppm is recovered as the slope of actual versus nominal instants, and the
// residual has the jitter's standard deviation.
#include "sim/effects/clock_jitter.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

TEST(ClockJitter, DriftAndJitterAreRecoveredFromTheInstants) {
    ClockJitterParams p;
    p.drift_ppm = 45.0;
    p.jitter_s = 2e-4;
    ClockJitter e(p);
    e.reset(8);
    const std::size_t n = 100000;
    const double period_s = 0.01;
    std::vector<double> nominal(n), actual(n);
    EffectContext ctx;
    ctx.channel = Channel::accel_x;
    for (std::size_t k = 0; k < n; ++k) {
        nominal[k] = static_cast<double>(k) * period_s;
        actual[k] = e.actual_instant_s(nominal[k], ctx);
    }
    // Least-squares line actual = a + b nominal.
    const double mt = test::mean(nominal), ma = test::mean(actual);
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        sxy += (nominal[k] - mt) * (actual[k] - ma);
        sxx += (nominal[k] - mt) * (nominal[k] - mt);
    }
    const double b = sxy / sxx;
    const double a = ma - b * mt;
    const double slope_sd = p.jitter_s / std::sqrt(sxx);
    EXPECT_NEAR((b - 1.0) * 1e6, 45.0, 5.0 * slope_sd * 1e6);
    std::vector<double> residual(n);
    for (std::size_t k = 0; k < n; ++k) residual[k] = actual[k] - (a + b * nominal[k]);
    EXPECT_NEAR(std::sqrt(test::variance(residual)) / p.jitter_s, 1.0, 5.0 / std::sqrt(2.0 * n));
    EXPECT_NEAR(test::autocorrelation(residual, 1), 0.0, 5.0 / std::sqrt(static_cast<double>(n)));  // white
}

TEST(ClockJitter, ApplyLeavesValuesAloneAndDefaultIsIdentity) {
    ClockJitter e(ClockJitterParams{});
    ChannelValues v = {1.0, 2.0, 3.0, 4.0};
    e.apply(v, EffectContext{});
    EXPECT_EQ(v, (ChannelValues{1.0, 2.0, 3.0, 4.0}));
    EXPECT_EQ(e.actual_instant_s(123.456, EffectContext{}), 123.456);
    EXPECT_EQ(e.stage(), Stage::timing);
}

}  // namespace
}  // namespace driftlab::sim
