// The bias processes of a model's effects as the filter's bias walks (host/nav/effect_noise.hpp): a Gauss-Markov
// bias walks as its increments do over a step short beside its correlation time, a rate random walk as K^2, a
// flicker floor as the walk that reaches it where its band ends; effects that are no bias add nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "host/nav/effect_noise.hpp"
#include "sim/model/model_file.hpp"

namespace driftlab::host::nav {
namespace {

constexpr double kRad = std::numbers::pi / 180.0;
constexpr double kG = 9.80665;

sim::SimModel with_effects(const std::string& toml) { return sim::parse_model(toml, "effects.toml"); }

TEST(EffectNoise, AGaussMarkovBiasWalksAsItsIncrementsOverAShortStep) {
    const EffectNoise e = effect_noise(with_effects(
        "[effects.gauss_markov]\nsigma_dps = 0.1\nsigma_g = [0.002, 0.001, 0.0]\ntau_s = [100.0, 50.0, 200.0, 1.0]\n"));
    EXPECT_EQ(e.used, "gauss_markov");
    // b_{k+1} - b_k = (phi - 1) b_k + sigma sqrt(1 - phi^2) eta: variance 2 sigma^2 (1 - phi), phi = exp(-dt / tau).
    constexpr double dt = 0.01;
    const double sigma[3] = {0.1 * kRad, 0.002 * kG, 0.001 * kG};
    const double tau[3] = {100.0, 50.0, 200.0};
    for (int k = 0; k < 3; ++k) {
        const double increments = 2.0 * sigma[k] * sigma[k] * (1.0 - std::exp(-dt / tau[k]));
        EXPECT_NEAR(e.bias_walk_psd[k] * dt, increments, 1e-3 * increments) << k;
    }
}

TEST(EffectNoise, ARateRandomWalkIsKSquaredAndFlickerReachesItsFloorWhereItsBandEnds) {
    const EffectNoise e =
        effect_noise(with_effects("[effects.rate_random_walk]\nk_dps_per_sqrt_s = 0.001\n"
                                  "[effects.flicker]\nb_dps = 0.02\nf_low_hz = 0.01\n"
                                  "[effects.spikes]\nrate_hz = 0.1\n"));
    EXPECT_EQ(e.used, "flicker, rate_random_walk");  // the chain's order
    // A random walk's ADEV is sqrt(q tau / 3): at tau = 1 / (2 pi f_low) it equals the flicker floor 0.664 B.
    const double tau = 1.0 / (2.0 * std::numbers::pi * 0.01);
    const double q_flicker = e.bias_walk_psd[0] - std::pow(0.001 * kRad, 2);
    EXPECT_NEAR(std::sqrt(q_flicker * tau / 3.0), 0.664282470267960 * 0.02 * kRad, 1e-12);
    EXPECT_EQ(e.bias_walk_psd[1], 0.0);
}

}  // namespace
}  // namespace driftlab::host::nav
