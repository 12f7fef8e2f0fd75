// E12 mains_alias: a DFT of the sampled output peaks at the predicted alias abs(f - f_s round(f/f_s)) with the
// pickup's amplitude; harmonics alias the same way; multiplexer skew shifts the phase by 2 pi f d.
#include "sim/effects/mains_alias.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

// |DFT| / (N/2) at bin k: the amplitude of a sinusoid that falls on bin k.
double dft_amplitude(const std::vector<double>& y, std::size_t k) {
    double re = 0.0, im = 0.0;
    const double n = static_cast<double>(y.size());
    for (std::size_t i = 0; i < y.size(); ++i) {
        const double a = 2.0 * std::numbers::pi * static_cast<double>(k * i % y.size()) / n;
        re += y[i] * std::cos(a);
        im -= y[i] * std::sin(a);
    }
    return std::hypot(re, im) * 2.0 / n;
}

TEST(MainsAlias, DftPeaksAtThePredictedAliasesOfFundamentalAndHarmonic) {
    MainsAliasParams p;
    p.amplitude_v = {0.002, 0.0, 0.0, 0.0};
    p.frequency_hz = 50.0;
    p.harmonic_ratio = {0.5};
    MainsAlias e(p);
    const double fs = 9.7;
    const std::size_t n = 1940;  // 200 s; the aliases fall on bins 300 and 600
    const double alias1 = MainsAlias::alias_frequency_hz(50.0, fs), alias2 = MainsAlias::alias_frequency_hz(100.0, fs);
    EXPECT_NEAR(alias1, 1.5, 1e-12);
    EXPECT_NEAR(alias2, 3.0, 1e-12);
    const auto y = test::run_added(e, n, 1.0 / fs);
    std::size_t peak = 0;
    double peak_amp = 0.0;
    for (std::size_t k = 1; k < n / 2; ++k) {
        const double a = dft_amplitude(y[0], k);
        if (a > peak_amp) {
            peak_amp = a;
            peak = k;
        }
    }
    EXPECT_EQ(peak, static_cast<std::size_t>(std::lround(alias1 * static_cast<double>(n) / fs)));
    EXPECT_NEAR(peak_amp, 0.002, 1e-9);
    EXPECT_NEAR(dft_amplitude(y[0], 600), 0.001, 1e-9);
}

TEST(MainsAlias, MuxSkewShiftsTheAliasedPhaseByTwoPiFD) {
    MainsAliasParams p;
    p.amplitude_v = {0.001, 0.001, 0.0, 0.0};
    p.mux_skew_s = {0.0, 0.0013, 0.0, 0.0};
    MainsAlias e(p);
    const double fs = 9.7;
    const std::size_t n = 1940;
    const auto y = test::run_added(e, n, 1.0 / fs);
    const auto t = test::time_grid(n, 1.0 / fs);
    const double d_phase = test::fit_tone(y[1], t, 1.5).phase_rad - test::fit_tone(y[0], t, 1.5).phase_rad;
    EXPECT_NEAR(test::angle_diff(d_phase, 2.0 * std::numbers::pi * 50.0 * 0.0013), 0.0, 1e-9);
}

}  // namespace
}  // namespace driftlab::sim
