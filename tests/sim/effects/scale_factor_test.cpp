// scale_factor: y = (1 + s/100) u on every channel; a conversion of one channel touches that channel alone.
#include "sim/effects/scale_factor.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

TEST(ScaleFactor, ScalesEachChannelsTrueInputByOnePlusItsError) {
    ScaleFactorParams p;
    p.error_pct = {1.5, -0.8, 0.0, 2.0};
    ScaleFactor e(p);
    EffectContext ctx;
    ctx.true_physical = {40.0, 0.25, -0.1, 1.0};
    ChannelValues v = ctx.true_physical;
    e.apply(v, ctx);
    for (std::size_t c = 0; c < kChannelCount; ++c)
        EXPECT_DOUBLE_EQ(v[c], (1.0 + p.error_pct[c] / 100.0) * ctx.true_physical[c]) << kChannelNames[c];
    // One conversion of the gyro leaves the other channels' values as they were.
    ChannelValues one = ctx.true_physical;
    ctx.channel = Channel::gyro;
    e.apply(one, ctx);
    EXPECT_DOUBLE_EQ(one[0], 40.0 * 1.015);
    for (std::size_t c = 1; c < kChannelCount; ++c) EXPECT_EQ(one[c], ctx.true_physical[c]);
}

TEST(ScaleFactor, DefaultsAreTheIdentity) {
    ScaleFactor e(ScaleFactorParams{});
    EffectContext ctx;
    ctx.true_physical = {80.0, 0.5, -0.5, 1.0};
    ChannelValues v = ctx.true_physical;
    e.apply(v, ctx);
    EXPECT_EQ(v, ctx.true_physical);
}

}  // namespace
}  // namespace driftlab::sim
