// E14 saturation: outputs never leave the rails, values inside are untouched, a clipped sinusoid has flat tops.
#include "sim/effects/saturation.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

TEST(Saturation, PhysicalRangeClipsAndKeepsValuesInside) {
    SaturationParams p;
    p.min_dps = -90.0;
    p.max_dps = 90.0;
    p.min_g = {-1.0, -1.0, 0.0};  // Z on 0 .. 2 g (the paper's gravity axis)
    p.max_g = {1.0, 1.0, 2.0};
    Saturation e(p);
    EXPECT_EQ(e.stage(), Stage::physical);
    std::size_t clipped = 0;
    for (int k = 0; k < 1000; ++k) {
        const double s = std::sin(2.0 * std::numbers::pi * k / 1000.0);
        ChannelValues in = {150.0 * s, 0.5 * s, 3.0 * s, 1.0 + 1.5 * s};
        ChannelValues v = in;
        e.apply(v, EffectContext{});
        EXPECT_EQ(v[0], std::clamp(in[0], -90.0, 90.0));
        EXPECT_EQ(v[1], in[1]);  // never beyond 1 g
        EXPECT_GE(v[2], -1.0);
        EXPECT_LE(v[2], 1.0);
        EXPECT_GE(v[3], 0.0);
        EXPECT_LE(v[3], 2.0);
        clipped += v[0] != in[0];
    }
    // 150 sin clipped at 90: fraction of time above = 1 - 2 asin(0.6) / pi.
    EXPECT_NEAR(static_cast<double>(clipped) / 1000.0, 1.0 - 2.0 * std::asin(0.6) / std::numbers::pi, 0.005);
}

TEST(Saturation, AnalogRailsActOnVolts) {
    const auto e = test::effect_from("saturation", "stage = \"analog\"\nmin_v = 0.2\nmax_v = [4.8, 4.8, 4.5, 4.8]");
    EXPECT_EQ(e->stage(), Stage::analog);
    ChannelValues v = {0.0, 2.5, 4.7, 6.0};
    e->apply(v, EffectContext{});
    EXPECT_EQ(v, (ChannelValues{0.2, 2.5, 4.5, 4.8}));
}

TEST(Saturation, MixingStagesIsAConfigError) {
    EXPECT_THROW(test::effect_from("saturation", "min_v = 0.2"), ConfigError);
    EXPECT_THROW(test::effect_from("saturation", "stage = \"analog\"\nmax_dps = 90.0"), ConfigError);
    EXPECT_THROW(test::effect_from("saturation", "min_dps = 10.0\nmax_dps = -10.0"), ConfigError);
}

}  // namespace
}  // namespace driftlab::sim
