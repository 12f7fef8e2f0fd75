// E3 flicker against IEEE 952: flat ADEV at sqrt(2 ln2 / pi) B = 0.664 B over the designed band.
#include "sim/effects/flicker.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

// Closed-form AVAR of one Gauss-Markov component (variance s2, correlation time T) at averaging time tau.
double gm_avar(double s2, double t_s, double tau_s) {
    const double x = tau_s / t_s;
    return s2 * (2.0 / x) * (1.0 - (3.0 - 4.0 * std::exp(-x) + std::exp(-2.0 * x)) / (2.0 * x));
}

FlickerParams params(double b, double f_low_hz, double f_high_hz) {
    FlickerParams p;
    p.b_dps = b;
    p.b_g = {b, b, b};
    p.f_low_hz = f_low_hz;
    p.f_high_hz = f_high_hz;
    return p;
}

const double kPlateau = std::sqrt(2.0 * std::log(2.0) / std::numbers::pi);  // 0.664

TEST(Flicker, ComponentsAreHalfADecadeApartCoveringTheBand) {
    Flicker f(params(1.0, 1e-3, 1.0));
    const auto& tau = f.component_tau_s();
    ASSERT_EQ(tau.size(), 9u);  // 6 half-decades + 1, plus one beyond each end
    for (std::size_t i = 1; i < tau.size(); ++i) EXPECT_NEAR(tau[i - 1] / tau[i], std::sqrt(10.0), 1e-9);
    EXPECT_NEAR(tau[1], 1.0 / (2.0 * std::numbers::pi * 1e-3), 1e-6);
}

TEST(Flicker, DesignedAdevIsWithinFivePercentOfPlateauOverTheBand) {
    const double b = 0.1, f_low = 1e-3, f_high = 1.0;
    Flicker f(params(b, f_low, f_high));
    const double s2 = std::pow(b * Flicker::component_sigma_per_b(), 2);
    const double lo = 2.5 / (2.0 * std::numbers::pi * f_high), hi = 1.0 / (2.0 * std::numbers::pi * f_low);
    for (double tau = lo; tau <= hi; tau *= 1.2) {
        double avar = 0.0;
        for (double t : f.component_tau_s()) avar += gm_avar(s2, t, tau);
        EXPECT_NEAR(std::sqrt(avar) / (kPlateau * b), 1.0, 0.05) << "tau " << tau;
    }
}

TEST(Flicker, SimulatedAdevIsFlatAtPlateau) {
    // f_high well below Nyquist (25 Hz): point samples alias whatever lies above it, which would lift short-tau
    // ADEV above the continuous-time design (docs/effects.md, flicker).
    const double b = 0.02, f_low = 0.005, f_high = 2.0, dt_s = 0.02;
    Flicker f(params(b, f_low, f_high));
    f.reset(2024);
    const auto y = test::run_added(f, 1 << 18, dt_s);  // 5243 s
    std::vector<double> adev;
    for (std::size_t m : {16u, 64u, 256u, 1024u}) {  // tau 0.32 .. 20.5 s, inside [0.2, 31.8] s
        double avar = 0.0;
        for (std::size_t c = 0; c < kChannelCount; ++c) avar += test::oavar(y[c], dt_s, m) / 4.0;
        adev.push_back(std::sqrt(avar));
        // 5 % design ripple + estimator scatter (4 channels, >= 1000 averages of 20 s).
        EXPECT_NEAR(adev.back() / (kPlateau * b), 1.0, 0.12) << "m " << m;
    }
    const double slope = std::log(adev.back() / adev.front()) / std::log(64.0);
    EXPECT_NEAR(slope, 0.0, 0.05);  // flat, unlike white (-1/2) or random walk (+1/2)
}

TEST(Flicker, InvalidBandIsIdentity) {
    Flicker f(params(1.0, 1.0, 0.5));
    EXPECT_TRUE(f.component_tau_s().empty());
    const auto y = test::run_added(f, 10, 1.0);
    for (double v : y[0]) EXPECT_EQ(v, 0.0);
}

}  // namespace
}  // namespace driftlab::sim
