// E8 supply_coupling: ripple and drift reach each channel as (r_c - r_adc) v dV / V_nom + p_c dV.
#include "sim/effects/supply_coupling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

TEST(SupplyCoupling, RippleAmplitudeFollowsRatiometricMismatchAndDcLevel) {
    SupplyCouplingParams p;
    p.sensor_ratiometric = {0.0, 1.0, 0.0, 0.5};
    p.adc_ratiometric = 1.0;
    p.pickup_v_per_v = {0.0, 0.0, 0.01, 0.0};
    p.ripple_v = 0.02;
    p.ripple_hz = 100.0;
    SupplyCoupling e(p);
    const ChannelValues dc = {2.5, 2.5, 1.0, 3.0};
    const double fs = 1000.0;
    const std::size_t n = 1000;
    const auto y = test::run_added(e, n, 1.0 / fs, dc);
    const auto t = test::time_grid(n, 1.0 / fs);
    // Channel 0: fully non-ratiometric sensor on a ratiometric ADC: -(v / V_nom) A_r.
    EXPECT_NEAR(test::fit_tone(y[0], t, 100.0).amplitude, 2.5 / 5.0 * 0.02, 1e-12);
    for (double v : y[1]) EXPECT_NEAR(v, 0.0, 1e-15);  // matched: no coupling
    // Channel 2: (0 - 1) * 1.0 / 5 + 0.01 pickup.
    EXPECT_NEAR(test::fit_tone(y[2], t, 100.0).amplitude, std::abs(-1.0 / 5.0 + 0.01) * 0.02, 1e-12);
    EXPECT_NEAR(test::fit_tone(y[3], t, 100.0).amplitude, 0.5 * 3.0 / 5.0 * 0.02, 1e-12);
}

TEST(SupplyCoupling, RegulatorDriftAndModelledSupplyShiftTheOutput) {
    SupplyCouplingParams p;
    p.sensor_ratiometric = {0.0, 0.0, 0.0, 0.0};
    p.drift_v = -0.05;
    p.drift_tau_s = 100.0;
    SupplyCoupling e(p);
    EffectContext ctx;
    ctx.t_s = 100.0;
    ctx.supply_v = 5.1;
    ChannelValues v = {2.5, 2.5, 2.5, 2.5};
    e.apply(v, ctx);
    const double dv = 0.1 - 0.05 * (1.0 - std::exp(-1.0));
    EXPECT_NEAR(e.supply_deviation_v(ctx), dv, 1e-15);
    EXPECT_NEAR(v[2], 2.5 * (1.0 - dv / 5.0), 1e-15);
}

// The wander is one Gauss-Markov path: stationary std sigma_w, lag-tau correlation e^-1 (closed form), and every
// channel converted at one instant sees the same deviation, through its own mismatch.
TEST(SupplyCoupling, WanderIsOneStationaryGaussMarkovPathSharedByTheChannels) {
    SupplyCouplingParams p;
    p.sensor_ratiometric = {0.0, 0.0, 1.0, 0.0};
    p.wander_v = 0.01;
    p.wander_tau_s = 20.0;
    SupplyCoupling e(p);
    e.reset(3);
    const ChannelValues dc = {2.5, 1.25, 2.5, 5.0};
    const std::size_t n = 400000;
    const auto y = test::run_added(e, n, 1.0, dc);
    std::vector<double> dv(n);
    for (std::size_t k = 0; k < n; ++k) {
        dv[k] = -y[0][k] / (2.5 / 5.0);
        EXPECT_NEAR(y[1][k], 0.5 * y[0][k], 1e-12);  // half the DC level, half the pickup
        EXPECT_EQ(y[2][k], 0.0);
        EXPECT_NEAR(y[3][k], 2.0 * y[0][k], 1e-12);
    }
    const double var = test::variance(dv);
    EXPECT_NEAR(std::sqrt(var), 0.01, 0.01 * 0.03);  // n / (2 tau) = 10 000 independent stretches: ~1 % sd
    double lag = 0.0;
    const double m = test::mean(dv);
    for (std::size_t k = 20; k < n; ++k) lag += (dv[k] - m) * (dv[k - 20] - m);
    EXPECT_NEAR(lag / static_cast<double>(n - 20) / var, std::exp(-1.0), 0.03);
}

// The wander is a function of t: one channel's whole log converted after another's (as the gap's replicates do)
// sees the path that all four converted at each instant see.
TEST(SupplyCoupling, WanderIsAFunctionOfTimeWhateverTheOrderOfConversions) {
    SupplyCouplingParams p;
    p.sensor_ratiometric = {0.0, 0.0, 0.0, 0.0};
    p.wander_v = 0.02;
    p.wander_tau_s = 5.0;
    SupplyCoupling per_sample(p), one_channel_after_another(p);
    per_sample.reset(9);
    one_channel_after_another.reset(9);
    EffectContext ctx;
    std::vector<ChannelValues> all(200, ChannelValues{2.5, 2.5, 2.5, 2.5});
    for (std::size_t k = 0; k < all.size(); ++k) {
        ctx.t_s = 0.37 * static_cast<double>(k);
        per_sample.apply(all[k], ctx);
    }
    for (Channel c : {Channel::gyro, Channel::accel_z}) {
        ctx.channel = c;
        for (std::size_t k = 0; k < all.size(); ++k) {
            ctx.t_s = 0.37 * static_cast<double>(k);
            ChannelValues one = {2.5, 2.5, 2.5, 2.5};
            one_channel_after_another.apply(one, ctx);
            EXPECT_DOUBLE_EQ(one[channel_index(c)], all[k][channel_index(c)]);
        }
    }
}

}  // namespace
}  // namespace driftlab::sim
