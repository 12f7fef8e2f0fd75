// E2 ambient_cycle against the Fourier series of the ambient wave through 1/(1 + s tau): fundamental and third
// harmonic amplitudes and the phase lag atan(w tau).
#include "sim/effects/ambient_cycle.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

AmbientCycleParams params(const char* wave, double lag_s) {
    AmbientCycleParams p;
    p.waveform = wave;
    p.amplitude_k_pp = 2.0;
    p.period_s = 1200.0;
    p.lag_s = lag_s;
    p.coupling_dps_per_k = 0.05;
    p.coupling_g_per_k = {0.001, -0.002, 0.0};
    return p;
}

TEST(AmbientCycle, SineIsAttenuatedAndDelayedByTheThermalLag) {
    AmbientCycle e(params("sine", 300.0));
    const double dt = 5.0;
    const std::size_t n = 2400;  // 10 periods
    const auto y = test::run_added(e, n, dt);
    const auto t = test::time_grid(n, dt);
    const double w = 2.0 * std::numbers::pi / 1200.0;
    const double gain = 1.0 / std::sqrt(1.0 + w * w * 300.0 * 300.0);
    const test::Tone tone = test::fit_tone(y[0], t, 1.0 / 1200.0);
    EXPECT_NEAR(tone.amplitude, 0.05 * 1.0 * gain, 1e-9);
    EXPECT_NEAR(test::angle_diff(tone.phase_rad, -std::atan(w * 300.0)), 0.0, 1e-9);
    EXPECT_NEAR(test::fit_tone(y[2], t, 1.0 / 1200.0).amplitude, 0.002 * gain, 1e-9);
    for (double v : y[3]) EXPECT_EQ(v, 0.0);
}

TEST(AmbientCycle, SquareWaveHarmonicsMatchItsFourierSeriesThroughTheLag) {
    const double tau = 200.0;
    AmbientCycle e(params("square", tau));
    const double dt = 1.0;
    const std::size_t n = 12000;  // 10 periods, integer number of samples per period
    const auto y = test::run_added(e, n, dt);
    const auto t = test::time_grid(n, dt);
    const double w = 2.0 * std::numbers::pi / 1200.0;
    // Square of peak A/2 = 1 K: odd harmonics 4/(pi h) each, times the lag's gain 1/sqrt(1 + (h w tau)^2).
    for (int h : {1, 3, 5}) {
        const double expected = 0.05 * 4.0 / (std::numbers::pi * h) / std::sqrt(1.0 + std::pow(h * w * tau, 2));
        const test::Tone tone = test::fit_tone(y[0], t, h / 1200.0);
        // Sampling a wave with a sharp corner at dt = P/1200 leaves O(dt/P) leakage.
        EXPECT_NEAR(tone.amplitude / expected, 1.0, 0.01) << "harmonic " << h;
    }
    EXPECT_LT(test::fit_tone(y[0], t, 2.0 / 1200.0).amplitude, 1e-3 * 0.05);  // no even harmonics
}

TEST(AmbientCycle, SquareWithoutLagIsTheThermostatWave) {
    AmbientCycle e(params("square", 0.0));
    const auto y = test::run_added(e, 1200, 1.0);
    for (std::size_t k = 0; k < 1200; ++k) EXPECT_DOUBLE_EQ(y[0][k], k < 600 ? 0.05 : -0.05) << k;
}

}  // namespace
}  // namespace driftlab::sim
