// E11 vibration: tone amplitudes (direct and aliased by the sampling rate), and the random part's rms and band.
#include "sim/effects/vibration.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

TEST(Vibration, TonesAppearWithTheirAmplitudesAndAliasAtTheSamplingRate) {
    VibrationParams p;
    p.tone_hz = {3.0, 130.0};
    p.tone_dps = {0.5, 0.0};
    p.tone_g_x = {0.01, 0.02};
    p.tone_g_z = {0.0, 0.04};
    p.tone_phase_rad = {0.3, 1.0};
    Vibration e(p);
    e.reset(1);
    const double fs = 100.0;
    const std::size_t n = 10000;
    const auto y = test::run_added(e, n, 1.0 / fs);
    const auto t = test::time_grid(n, 1.0 / fs);
    EXPECT_NEAR(test::fit_tone(y[0], t, 3.0).amplitude, 0.5, 1e-9);
    EXPECT_NEAR(test::fit_tone(y[1], t, 3.0).amplitude, 0.01, 1e-9);
    EXPECT_NEAR(test::angle_diff(test::fit_tone(y[1], t, 3.0).phase_rad, 0.3), 0.0, 1e-9);
    // 130 Hz sampled at 100 Hz shows at abs(130 - 100) = 30 Hz with its full amplitude.
    EXPECT_NEAR(test::fit_tone(y[3], t, 30.0).amplitude, 0.04, 1e-9);
    EXPECT_NEAR(test::fit_tone(y[1], t, 30.0).amplitude, 0.02, 1e-9);
    for (double v : y[2]) EXPECT_EQ(v, 0.0);
}

TEST(Vibration, RandomPartHasItsRmsAndStaysInItsBand) {
    VibrationParams p;
    p.random_rms_g = {0.01, 0.02, 0.0};
    p.band_low_hz = 5.0;
    p.band_high_hz = 20.0;
    p.random_lines = 64;
    Vibration e(p);
    e.reset(42);
    const double fs = 100.0;
    const std::size_t n = 60000;  // 600 s: line pairs closer than 1/600 Hz are rare among 64 lines
    const auto y = test::run_added(e, n, 1.0 / fs);
    EXPECT_NEAR(std::sqrt(test::variance(y[1])) / 0.01, 1.0, 0.03);
    EXPECT_NEAR(std::sqrt(test::variance(y[2])) / 0.02, 1.0, 0.03);
    // Power outside the band: project on tones at 0.5..4.5 Hz and 25..45 Hz; all tiny.
    const auto t = test::time_grid(n, 1.0 / fs);
    for (double f : {0.5, 2.0, 4.5, 25.0, 35.0, 45.0}) EXPECT_LT(test::fit_tone(y[1], t, f).amplitude, 1e-3 * 0.01);
}

TEST(Vibration, IsAnInputAndReproducibleForASeed) {
    VibrationParams p;
    p.random_rms_dps = 1.0;
    Vibration a(p), b(p);
    EXPECT_TRUE(a.is_input());
    a.reset(5);
    b.reset(5);
    EXPECT_EQ(test::run_added(a, 100, 0.01), test::run_added(b, 100, 0.01));
    b.reset(6);
    EXPECT_NE(test::run_added(a, 100, 0.01)[0], test::run_added(b, 100, 0.01)[0]);
}

}  // namespace
}  // namespace driftlab::sim
