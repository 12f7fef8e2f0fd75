// E5 gauss_markov against its closed forms: stationary variance sigma^2, autocorrelation exp(-lag/tau),
// ADEV peak 0.618 sigma at 1.89 tau.
#include "sim/effects/gauss_markov.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

using test::run_added;

GaussMarkovParams params(double sigma, double tau_s) {
    GaussMarkovParams p;
    p.sigma_dps = sigma;
    p.sigma_g = {sigma, sigma, sigma};
    p.tau_s.fill(tau_s);
    return p;
}

TEST(GaussMarkov, StationaryVarianceIsSigmaSquared) {
    GaussMarkov gm(params(0.05, 10.0));
    gm.reset(11);
    const std::size_t n = 200000;
    const auto y = run_added(gm, n, 1.0);
    // Var of s^2 for an AR(1) with phi: 2 sigma^4 (1 + phi^2) / ((1 - phi^2) n); 5 estimator sigmas.
    const double phi = std::exp(-0.1);
    const double rel_sd = std::sqrt(2.0 * (1.0 + phi * phi) / ((1.0 - phi * phi) * static_cast<double>(n)));
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        EXPECT_NEAR(test::variance(y[c]) / (0.05 * 0.05), 1.0, 5.0 * rel_sd) << kChannelNames[c];
    }
}

TEST(GaussMarkov, AutocorrelationIsExpMinusLagOverTau) {
    GaussMarkov gm(params(1.0, 20.0));
    gm.reset(3);
    const std::size_t n = 400000;
    const double dt_s = 0.5;
    const auto y = run_added(gm, n, dt_s);
    // Bartlett: sd of r(k) for AR(1) ~ sqrt((1 + phi^2) / ((1 - phi^2) n)) at most.
    const double phi = std::exp(-dt_s / 20.0);
    const double sd = std::sqrt((1.0 + phi * phi) / ((1.0 - phi * phi) * static_cast<double>(n)));
    for (std::size_t lag : {1u, 10u, 40u, 80u}) {
        const double expected = std::exp(-static_cast<double>(lag) * dt_s / 20.0);
        EXPECT_NEAR(test::autocorrelation(y[0], lag), expected, 5.0 * sd) << "lag " << lag;
    }
}

TEST(GaussMarkov, ExactDiscretisationHoldsForIrregularInstants) {
    // Per-conversion use gives uneven dt: the variance must stay sigma^2 and r(t) exp(-t/tau) whatever the steps.
    GaussMarkov gm(params(1.0, 5.0));
    gm.reset(5);
    const std::size_t n = 200000;
    std::vector<double> y(n);
    EffectContext ctx;
    ctx.channel = Channel::accel_y;
    for (std::size_t k = 0; k < n; ++k) {
        ctx.dt_s = k == 0 ? 0.0 : (k % 2 == 0 ? 0.2 : 1.8);  // mean step 1 s
        ChannelValues v{};
        gm.apply(v, ctx);
        y[k] = v[channel_index(Channel::accel_y)];
        EXPECT_EQ(v[0], 0.0);  // other channels untouched in per-conversion mode
    }
    EXPECT_NEAR(test::variance(y), 1.0, 0.05);
    EXPECT_NEAR(test::autocorrelation(y, 2), std::exp(-2.0 / 5.0), 0.03);  // two steps = 2 s
}

// Across power-ons (one seed each): the first value is already stationary, b_0 ~ N(0, sigma^2), and the value dt
// later reverts toward 0, E[b_1 | b_0] = phi b_0 with phi = exp(-dt / tau), scattering by sigma^2 (1 - phi^2) about
// it. n = 4 channels x 20000 seeds independent pairs: a variance is known to sqrt(2 / n) relative, the regression
// slope to sqrt((1 - phi^2) / n), the mean to sigma / sqrt(n); every check is 5 of those.
TEST(GaussMarkov, StartsStationaryAndRevertsByPhiAcrossPowerOns) {
    const double sigma = 2.0, tau_s = 5.0, dt_s = 2.0;
    GaussMarkov gm(params(sigma, tau_s));
    const double phi = std::exp(-dt_s / tau_s);
    double sum0 = 0.0, s00 = 0.0, s01 = 0.0, s11 = 0.0;
    const std::size_t seeds = 20000;
    for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
        gm.reset(seed);
        const auto y = run_added(gm, 2, dt_s);
        for (std::size_t c = 0; c < kChannelCount; ++c) {
            sum0 += y[c][0];
            s00 += y[c][0] * y[c][0];
            s01 += y[c][0] * y[c][1];
            s11 += y[c][1] * y[c][1];
        }
    }
    const double n = static_cast<double>(seeds * kChannelCount);
    const double slope = s01 / s00;
    const double residual_var = (s11 - 2.0 * phi * s01 + phi * phi * s00) / n;  // of b_1 - phi b_0, mean 0
    EXPECT_NEAR(sum0 / n, 0.0, 5.0 * sigma / std::sqrt(n));
    EXPECT_NEAR(s00 / n / (sigma * sigma), 1.0, 5.0 * std::sqrt(2.0 / n));
    EXPECT_NEAR(slope, phi, 5.0 * std::sqrt((1.0 - phi * phi) / n));
    EXPECT_NEAR(residual_var / (sigma * sigma * (1.0 - phi * phi)), 1.0, 5.0 * std::sqrt(2.0 / n));
}

TEST(GaussMarkov, AdevPeaksAt0618SigmaNear189Tau) {
    GaussMarkov gm(params(1.0, 8.0));
    gm.reset(21);
    const auto y = run_added(gm, 1 << 19, 1.0);
    // Closed form at tau = 15 s (1.875 T): sigma^2 (2T/tau)(1 - T/(2 tau)(3 - 4e^-x + e^-2x)), x = tau/T.
    const double x = 15.0 / 8.0;
    const double avar = (2.0 / x) * (1.0 - (3.0 - 4.0 * std::exp(-x) + std::exp(-2.0 * x)) / (2.0 * x));
    EXPECT_NEAR(std::sqrt(avar), 0.618, 0.002);  // the reference value itself
    double sum = 0.0;
    for (std::size_t c = 0; c < kChannelCount; ++c) sum += test::oavar(y[c], 1.0, 15);
    // 4 channels x ~35000 s / 15 s: EDF in the thousands, ADEV within a few percent.
    EXPECT_NEAR(std::sqrt(sum / 4.0), std::sqrt(avar), 0.06 * std::sqrt(avar));
}

TEST(GaussMarkov, DefaultParametersAreIdentity) {
    GaussMarkov gm(GaussMarkovParams{});
    gm.reset(1);
    const auto y = run_added(gm, 1000, 0.1, {1.0, 2.0, 3.0, 4.0});
    for (const auto& ch : y)
        for (double v : ch) EXPECT_EQ(v, 0.0);
}

}  // namespace
}  // namespace driftlab::sim
