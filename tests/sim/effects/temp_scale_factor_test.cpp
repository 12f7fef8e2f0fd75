// temp_scale_factor: output slope versus temperature equals (s/100) u; without a modelled temperature, identity.
#include "sim/effects/temp_scale_factor.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

TEST(TempScaleFactor, SlopeVersusTemperatureIsTempcoTimesInput) {
    TempScaleFactorParams p;
    p.scale_pct_per_k = {0.05, -0.02, 0.0, 0.01};
    p.reference_degc = 25.0;
    TempScaleFactor e(p);
    EffectContext ctx;
    ctx.true_physical = {40.0, 0.5, 0.0, 1.0};
    std::array<std::vector<double>, kChannelCount> y;
    std::vector<double> temps;
    for (double temp = 5.0; temp <= 65.0; temp += 5.0) {
        ctx.temperature_degc = temp;
        ChannelValues v = ctx.true_physical;
        e.apply(v, ctx);
        temps.push_back(temp);
        for (std::size_t c = 0; c < kChannelCount; ++c) y[c].push_back(v[c]);
        if (temp == 25.0) {
            for (std::size_t c = 0; c < kChannelCount; ++c) EXPECT_EQ(v[c], ctx.true_physical[c]);
        }
    }
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        const double slope = (y[c].back() - y[c].front()) / (temps.back() - temps.front());
        EXPECT_NEAR(slope, p.scale_pct_per_k[c] / 100.0 * ctx.true_physical[c], 1e-12) << kChannelNames[c];
    }
}

TEST(TempScaleFactor, UnmodelledTemperatureLeavesValuesUnchanged) {
    TempScaleFactorParams p;
    p.scale_pct_per_k.fill(1.0);
    TempScaleFactor e(p);
    EffectContext ctx;  // temperature NaN
    ctx.true_physical = {10.0, 1.0, 1.0, 1.0};
    ChannelValues v = {1.0, 2.0, 3.0, 4.0};
    e.apply(v, ctx);
    EXPECT_EQ(v, (ChannelValues{1.0, 2.0, 3.0, 4.0}));
}

}  // namespace
}  // namespace driftlab::sim
