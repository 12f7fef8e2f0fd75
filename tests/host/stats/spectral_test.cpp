// Octave-grid ADEV, band power, band coherence and lag-band ACF against closed forms for white and AR(1) noise; the
// spectrum they share against a direct DFT.
#include <cmath>
#include <complex>
#include <numbers>

#include <gtest/gtest.h>

#include "white_noise.hpp"

#include "host/stats/spectral.hpp"

namespace driftlab::host::stats {
namespace {

using testing::white;

TEST(Spectral, WhiteNoiseAdevFallsAsOneOverRootM) {
    const auto y = white(1 << 16, 2.0, 1);
    const auto dev = octave_oadev(y, 256);
    ASSERT_EQ(dev.size(), 9u);
    for (std::size_t j = 0; j < dev.size(); ++j) {
        const double expected = 2.0 / std::sqrt(std::ldexp(1.0, static_cast<int>(j)));
        EXPECT_NEAR(dev[j] / expected, 1.0, 0.08) << "m = " << (1 << j);
    }
}

// 100 samples zero-padded to 128 points: the spectrum keeps bins 0..63, the ones below Nyquist the bands use, each the
// direct DFT of the series with its mean removed and a Hann window over its 100 samples.
TEST(Spectral, TheSpectrumKeepsTheBinsBelowNyquistOfTheWindowedSeries) {
    const std::size_t n = 100, nfft = 128;
    const auto y = white(n, 1.0, 7);
    const BandSpectrum s = band_spectrum(y);
    EXPECT_EQ(s.length, n);
    ASSERT_EQ(s.bins.size(), nfft / 2);
    double mean = 0.0;
    for (double v : y) mean += v / static_cast<double>(n);
    for (std::size_t k = 0; k < nfft / 2; ++k) {
        std::complex<double> direct = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const double hann =
                0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * (static_cast<double>(i) + 0.5) / static_cast<double>(n));
            direct += (y[i] - mean) * hann *
                      std::polar(1.0, -2.0 * std::numbers::pi * static_cast<double>(k * i) / static_cast<double>(nfft));
        }
        EXPECT_NEAR(std::abs(s.bins[k] - direct), 0.0, 1e-10) << "bin " << k;
    }
}

TEST(Spectral, WhiteNoiseBandPowerIsFlatAtHannPowerFactor) {
    // E|X_k|^2 / n = sigma^2 * mean(w^2) = 3/8 sigma^2 for the Hann window, in every band. A band mean of `bins`
    // periodogram values of white noise, Hann-windowed (neighbours correlated: 1.94 bins make one independent), has a
    // relative standard deviation sqrt(1.94 / bins): 4 of them (2 % in band 0, where a wrong window factor shows).
    const double sigma = 1.5;
    const std::size_t n = 1 << 14;
    const auto y = white(n, sigma, 2);
    const auto p = octave_band_power(band_spectrum(y));
    ASSERT_GE(p.size(), 8u);
    for (std::size_t j = 0; j < 7; ++j) {  // bands of >= 64 bins
        const double bins = std::ldexp(static_cast<double>(n) / 2.0, -static_cast<int>(j) - 1);
        EXPECT_NEAR(p[j] / (0.375 * sigma * sigma), 1.0, 4.0 * std::sqrt(1.94 / bins)) << "band " << j;
    }
}

// x = s + n1, y = s + n2 with white s, n1, n2 of unit variance: coherence (1 / (1 + 1))^2 = 1/4 in every band.
// With y's share of s delayed by d samples the cross term's phase turns across band j (width w = pi / 2^(j+1)):
// 1/4 (sin(d w / 2) / (d w / 2))^2. Independent series leave only the estimator's bias, about the inverse of the
// independent bins (a Hann window halves them).
TEST(Spectral, BandCoherenceOfASharedComponentMatchesItsShare) {
    const std::size_t n = 1 << 14;
    const std::size_t d = 2;
    const auto shared = white(n, 1.0, 4), n1 = white(n, 1.0, 5), n2 = white(n, 1.0, 6);
    std::vector<double> x(n), y(n), lagged(n);
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = shared[i] + n1[i];
        y[i] = shared[i] + n2[i];
        lagged[i] = (i >= d ? shared[i - d] : 0.0) + n2[i];
    }
    const BandSpectrum sx = band_spectrum(x);
    const auto coh = octave_band_coherence(sx, band_spectrum(y));
    const auto none = octave_band_coherence(band_spectrum(n1), band_spectrum(n2));
    const auto self = octave_band_coherence(sx, sx);
    const auto lag = octave_band_coherence(sx, band_spectrum(lagged));
    ASSERT_EQ(coh.size(), octave_band_power(sx).size() - 2);  // not the bands of 2 and 4 bins
    for (std::size_t j = 0; j < 5; ++j) {  // bands of >= 256 bins: the lower ones average too few for a tight check
        const double bins = std::ldexp(static_cast<double>(n) / 2.0, -static_cast<int>(j) - 1);
        const double half_turn = static_cast<double>(d) * std::numbers::pi / std::ldexp(2.0, static_cast<int>(j)) / 2.0;
        // An estimate of squared coherence g over K independent bins (K = bins / 1.94 under the Hann window) scatters
        // by sqrt(2 g (1 - g)^2 / K) and reads high by about (1 - g)^2 / K: 4 of the one beside the other.
        const double k = bins / 1.94;
        const auto tolerance = [k](double g) {
            return 4.0 * std::sqrt(2.0 * g * (1.0 - g) * (1.0 - g) / k) + (1.0 - g) * (1.0 - g) / k;
        };
        const double lag_share = 0.25 * std::pow(std::sin(half_turn) / half_turn, 2);
        EXPECT_NEAR(coh[j], 0.25, tolerance(0.25)) << "band " << j;
        EXPECT_NEAR(lag[j], lag_share, tolerance(lag_share)) << "band " << j;
        EXPECT_LT(none[j], 2.0 * 4.0 / bins + 0.005) << "band " << j;
        EXPECT_NEAR(self[j], 1.0, 1e-12) << "band " << j;
    }
}

TEST(Spectral, Ar1LagBandsMatchGeometricAutocorrelation) {
    const double phi = 0.8;
    const auto e = white(1 << 16, 1.0, 3);
    std::vector<double> y(e.size());
    y[0] = e[0];
    for (std::size_t i = 1; i < y.size(); ++i) y[i] = phi * y[i - 1] + e[i];
    const auto r = octave_lag_acf(y, 64);
    ASSERT_GE(r.size(), 3u);
    EXPECT_NEAR(r[0], phi, 0.02);
    EXPECT_NEAR(r[1], (phi * phi + phi * phi * phi) / 2.0, 0.03);
    double band = 0.0;
    for (int k = 4; k < 8; ++k) band += std::pow(phi, k) / 4.0;
    EXPECT_NEAR(r[2], band, 0.03);
}

}  // namespace
}  // namespace driftlab::host::stats
