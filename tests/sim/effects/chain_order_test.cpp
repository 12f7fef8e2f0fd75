// The chain contract of effect.hpp: application order by rank, and input effects reaching the true input of every
// channel so a coupling sees motion on axes other than the converted one.
#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

TEST(EffectChainContract, RankPutsInputsFirstInlBeforeDnlAndClippingLast) {
    EXPECT_LT(application_rank("vibration"), application_rank("g_sensitivity"));
    EXPECT_LT(application_rank("vibration"), application_rank("cross_axis"));
    EXPECT_LT(application_rank("adc_inl"), application_rank("adc_dnl"));
    EXPECT_LT(application_rank("adc_dnl"), application_rank("spikes"));
    for (const EffectInfo& info : list_effects()) {
        if (info.stage == Stage::physical && info.name != "saturation") {
            EXPECT_LT(application_rank(info.name), application_rank("saturation")) << info.name;
        }
    }
    EXPECT_EQ(application_rank("no_such_effect"), list_effects().size());
}

TEST(EffectChainContract, GyroConversionSeesAccelVibrationThroughGSensitivity) {
    const auto vib = test::effect_from("vibration", "tone_hz = [7.0]\ntone_g_z = [0.5]\ntone_dps = [0.0]");
    const auto gs = test::effect_from("g_sensitivity", "g_dps_per_g = [0.0, 0.0, 0.2]");
    for (double t : {0.01, 0.033, 0.1}) {
        EffectContext ctx;
        ctx.t_s = t;
        ctx.channel = Channel::gyro;
        ctx.true_physical = {0.0, 0.0, 0.0, 1.0};
        ChannelValues v = ctx.true_physical;
        apply_in_chain(*vib, v, ctx);
        apply_in_chain(*gs, v, ctx);
        const double a_z = 1.0 + 0.5 * std::sin(2.0 * std::numbers::pi * 7.0 * t);
        EXPECT_NEAR(ctx.true_physical[3], a_z, 1e-15);
        EXPECT_NEAR(v[0], 0.2 * a_z, 1e-15);  // the gyro's own vibration is zero: only the coupling
        EXPECT_EQ(v[3], 1.0);                 // the accel channel is not converted at this instant
    }
}

TEST(EffectChainContract, NonInputEffectsAreAppliedUnchanged) {
    const auto gm = test::effect_from("gauss_markov", "sigma_dps = 1.0");
    const auto twin = test::effect_from("gauss_markov", "sigma_dps = 1.0");
    EffectContext ctx;
    ctx.dt_s = 1.0;
    ChannelValues a{}, b{};
    apply_in_chain(*gm, a, ctx);
    twin->apply(b, ctx);
    EXPECT_EQ(a, b);
    EXPECT_EQ(ctx.true_physical, (ChannelValues{}));
}

}  // namespace
}  // namespace driftlab::sim
