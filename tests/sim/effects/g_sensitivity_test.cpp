// E10 g_sensitivity: gyro bias = G . a (+ G2 . a^2); under sinusoidal vibration of amplitude A the rectified
// mean is G2 A^2 / 2.
#include "sim/effects/g_sensitivity.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

TEST(GSensitivity, GyroBiasIsLinearInAcceleration) {
    GSensitivityParams p;
    p.g_dps_per_g = {0.1, -0.2, 0.05};
    GSensitivity e(p);
    EffectContext ctx;
    ctx.true_physical = {0.0, 0.3, -0.4, 1.0};
    ChannelValues v{};
    e.apply(v, ctx);
    EXPECT_NEAR(v[0], 0.1 * 0.3 + 0.2 * 0.4 + 0.05 * 1.0, 1e-15);
    EXPECT_EQ(v[1], 0.0);
    EXPECT_EQ(v[3], 0.0);
}

TEST(GSensitivity, QuadraticTermRectifiesVibrationIntoMeanBias) {
    GSensitivityParams p;
    p.g2_dps_per_g2 = {0.0, 0.0, 0.4};
    GSensitivity e(p);
    const double amp_g = 0.5, f_hz = 7.0;
    double sum = 0.0;
    const int n = 7000;  // 10 s, integer number of cycles
    for (int k = 0; k < n; ++k) {
        EffectContext ctx;
        ctx.channel = Channel::gyro;
        ctx.true_physical = {0.0, 0.0, 0.0, amp_g * std::sin(2.0 * std::numbers::pi * f_hz * k / 700.0)};
        ChannelValues v{};
        e.apply(v, ctx);
        sum += v[0];
    }
    EXPECT_NEAR(sum / n, 0.4 * amp_g * amp_g / 2.0, 1e-12);
}

}  // namespace
}  // namespace driftlab::sim
