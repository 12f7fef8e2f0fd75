// bandwidth: a first-order low-pass, checked against its step response 1 - e^(-t/tau) and its amplitude response
// 1/sqrt(1 + (f/f_c)^2); a cutoff of 0 is the identity, and the filter starts settled.
#include "sim/effects/bandwidth.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Bandwidth, AStepRisesAsOneMinusTheExponentialOfTheTimeConstant) {
    BandwidthParams p;
    p.cutoff_hz = {7.0, 0.0, 0.0, 0.0};
    Bandwidth e(p);
    const double tau = 1.0 / (2.0 * kPi * 7.0), dt = 0.001;
    EffectContext ctx;
    ctx.channel = Channel::gyro;
    ChannelValues v{0.0, 0.0, 0.0, 1.0};
    e.apply(v, ctx);  // the first instant: settled at 0
    EXPECT_EQ(v[0], 0.0);
    ctx.dt_s = dt;
    for (int k = 1; k <= 100; ++k) {
        ChannelValues step{50.0, 0.3, 0.0, 1.0};
        e.apply(step, ctx);
        EXPECT_NEAR(step[0], 50.0 * (1.0 - std::exp(-k * dt / tau)), 1e-9) << k;
        EXPECT_EQ(step[1], 0.3) << "a channel without a cutoff is not filtered";
    }
}

TEST(Bandwidth, ASineIsAttenuatedAsAFirstOrderLag) {
    for (double f : {2.0, 7.0, 20.0}) {
        BandwidthParams p;
        p.cutoff_hz.fill(7.0);
        Bandwidth e(p);
        EffectContext ctx;
        const double dt = 1e-4;
        double peak = 0.0;
        for (int k = 0; k < 40000; ++k) {
            ChannelValues v{};
            v[0] = std::sin(2.0 * kPi * f * k * dt);
            e.apply(v, ctx);
            ctx.dt_s = dt;
            if (k > 20000) peak = std::max(peak, v[0]);  // settled after two seconds
        }
        // A held input adds half a step of delay, nothing to the amplitude at 1e-4 s steps.
        EXPECT_NEAR(peak, 1.0 / std::sqrt(1.0 + (f / 7.0) * (f / 7.0)), 2e-3) << f;
    }
}

TEST(Bandwidth, DefaultsAreTheIdentity) {
    Bandwidth e(BandwidthParams{});
    EffectContext ctx;
    ctx.dt_s = 0.01;
    ChannelValues v{80.0, 0.5, -0.5, 1.0};
    const ChannelValues before = v;
    e.apply(v, ctx);
    EXPECT_EQ(v, before);
}

}  // namespace
}  // namespace driftlab::sim
