// E15 spikes: the count of spikes is Poisson with mean N (1 - exp(-lambda dt)), amplitudes have the configured
// scale, bit flips change the code by exactly one power of two.
#include "sim/effects/spikes.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

TEST(Spikes, CountMatchesPoissonRateWithinFiveSigma) {
    const auto e = test::effect_from("spikes", "rate_hz = [2.0, 0.5, 0.0, 0.1]\nscale_counts = 10.0");
    e->reset(31);
    const double dt = 0.01;
    const std::size_t n = 1'000'000;
    const auto y = test::run_added(*e, n, dt);
    const ChannelValues rate = {2.0, 0.5, 0.0, 0.1};
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        std::size_t count = 0;
        for (std::size_t k = 1; k < n; ++k) count += y[c][k] != 0.0;
        const double p = 1.0 - std::exp(-rate[c] * dt);
        const double mean = p * static_cast<double>(n - 1);
        EXPECT_NEAR(static_cast<double>(count), mean, 5.0 * std::sqrt(mean * (1.0 - p)) + 1e-9) << kChannelNames[c];
    }
}

TEST(Spikes, GaussianAmplitudesHaveTheConfiguredScale) {
    const auto e = test::effect_from("spikes", "stage = \"analog\"\nrate_hz = 20.0\nscale_v = 0.05");
    EXPECT_EQ(e->stage(), Stage::analog);
    e->reset(4);
    const auto y = test::run_added(*e, 500'000, 0.01);
    std::vector<double> amps;
    for (double v : y[1])
        if (v != 0.0) amps.push_back(v);
    ASSERT_GT(amps.size(), 10000u);
    EXPECT_NEAR(test::mean(amps), 0.0, 5.0 * 0.05 / std::sqrt(static_cast<double>(amps.size())));
    EXPECT_NEAR(std::sqrt(test::variance(amps)) / 0.05, 1.0, 5.0 / std::sqrt(2.0 * static_cast<double>(amps.size())));
}

TEST(Spikes, StudentTAmplitudesHaveHeavierTailsThanGaussian) {
    const auto e = test::effect_from("spikes",
                                     "rate_hz = 50.0\nscale_counts = 1.0\ndistribution = \"student_t\"\n"
                                     "student_dof = 5");
    e->reset(12);
    const auto y = test::run_added(*e, 400'000, 0.01);
    std::vector<double> amps;
    for (double v : y[0])
        if (v != 0.0) amps.push_back(v);
    // Two-sided tail probabilities of t_5: P(|T| > 2.015) = 0.10, P(|T| > 4.032) = 0.01 (a Gaussian gives
    // 0.044 and 5.5e-5). Binomial counts, 5 sigmas.
    const double n = static_cast<double>(amps.size());
    for (const auto& [q, p] : {std::pair{2.015, 0.10}, std::pair{4.032, 0.01}}) {
        double beyond = 0.0;
        for (double a : amps) beyond += std::abs(a) > q;
        EXPECT_NEAR(beyond / n, p, 5.0 * std::sqrt(p * (1.0 - p) / n)) << "q " << q;
    }
}

TEST(Spikes, BitFlipsChangeTheCodeByOnePowerOfTwo) {
    const auto e = test::effect_from("spikes", "rate_hz = 100.0\ndistribution = \"bit_flip\"");
    e->reset(2);
    std::size_t flips = 0;
    EffectContext ctx;
    ctx.dt_s = 0.01;
    for (int k = 0; k < 10000; ++k) {
        ChannelValues v = {512.0, 300.2, 1023.0, 0.0};
        const ChannelValues rounded = {512.0, 300.0, 1023.0, 0.0};
        e->apply(v, ctx);
        for (std::size_t c = 0; c < kChannelCount; ++c) {
            if (v[c] == (c == 1 ? 300.2 : rounded[c])) continue;
            ++flips;
            const auto diff = static_cast<std::int64_t>(std::abs(v[c] - rounded[c]));
            EXPECT_TRUE(diff > 0 && (diff & (diff - 1)) == 0 && diff < 1024) << diff;
            EXPECT_GE(v[c], 0.0);
            EXPECT_LE(v[c], 1023.0);
        }
    }
    EXPECT_GT(flips, 0u);
}

TEST(Spikes, BitFlipNeedsTheConverterStage) {
    EXPECT_THROW(test::effect_from("spikes", "stage = \"analog\"\ndistribution = \"bit_flip\""), ConfigError);
    EXPECT_THROW(test::effect_from("spikes", "scale_v = 0.1"), ConfigError);
}

}  // namespace
}  // namespace driftlab::sim
