// Octave-grid ADEV, band power and lag-band ACF against closed forms for white and AR(1) noise.
#include <cmath>

#include <gtest/gtest.h>

#include "gap_fixtures.hpp"

#include "host/gap/spectral.hpp"

namespace driftlab::host::gap {
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

TEST(Spectral, WhiteNoiseBandPowerIsFlatAtHannPowerFactor) {
    // E|X_k|^2 / n = sigma^2 * mean(w^2) = 3/8 sigma^2 for the Hann window, in every band.
    const double sigma = 1.5;
    const auto y = white(1 << 14, sigma, 2);
    const auto p = octave_band_power(y);
    ASSERT_GE(p.size(), 8u);
    for (std::size_t j = 0; j < 7; ++j)  // bands of >= 64 bins: the lower ones average too few for a tight check
        EXPECT_NEAR(p[j] / (0.375 * sigma * sigma), 1.0, 0.12) << "band " << j;
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
}  // namespace driftlab::host::gap
