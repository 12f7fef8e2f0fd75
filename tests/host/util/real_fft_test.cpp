// The real transforms against a direct DFT, their inverse, and the per-thread plans (evicted, on several threads).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <thread>
#include <vector>

#include "host/util/real_fft.hpp"

namespace driftlab::host {
namespace {

std::vector<double> series(std::size_t n) {
    std::vector<double> x(n);
    for (std::size_t t = 0; t < n; ++t)
        x[t] = std::sin(0.37 * static_cast<double>(t * t % 97)) + 0.01 * static_cast<double>(t);
    return x;
}

std::complex<double> direct_bin(const std::vector<double>& x, std::size_t k) {
    std::complex<double> sum = 0.0;
    const double n = static_cast<double>(x.size());
    for (std::size_t t = 0; t < x.size(); ++t)
        sum += x[t] * std::polar(1.0, -2.0 * std::numbers::pi * static_cast<double>(k * t % x.size()) / n);
    return sum;
}

// Even, odd, prime and one point (no transform).
TEST(RealFft, TheHalfSpectrumHoldsTheBinsUpToNyquistOfADirectTransform) {
    for (std::size_t n : {96u, 98u, 75u, 97u, 2u, 1u}) {
        const std::vector<double> x = series(n);
        const std::vector<std::complex<double>> half = half_spectrum(x);
        ASSERT_EQ(half.size(), n / 2 + 1) << "n = " << n;
        for (std::size_t k = 0; k < half.size(); ++k) {
            const std::complex<double> want = direct_bin(x, k);
            EXPECT_NEAR(half[k].real(), want.real(), 1e-10) << "n = " << n << ", bin " << k;
            EXPECT_NEAR(half[k].imag(), want.imag(), 1e-10) << "n = " << n << ", bin " << k;
        }
    }
}

TEST(RealFft, NoSamplesHaveNoBins) { EXPECT_TRUE(half_spectrum({}).empty()); }

TEST(RealFft, TheInverseGivesTheSeriesBack) {
    for (std::size_t n : {96u, 75u, 1u}) {
        const std::vector<double> x = series(n);
        const std::vector<double> back = real_series(half_spectrum(x), n);
        ASSERT_EQ(back.size(), n);
        for (std::size_t t = 0; t < n; ++t) EXPECT_NEAR(back[t], x[t], 1e-12) << "n = " << n << ", t = " << t;
    }
}

TEST(RealFft, TheInverseOfAWrongNumberOfBinsIsRefused) {
    EXPECT_THROW(real_series(std::vector<std::complex<double>>(10), 96), std::invalid_argument);
    EXPECT_THROW(real_series({}, 0), std::invalid_argument);
}

// More lengths than a thread keeps plans for: a length planned again after its plan was dropped gives the same digits.
TEST(RealFft, ALengthPlannedAgainGivesTheSameDigits) {
    const std::vector<double> x = series(120);
    const std::vector<std::complex<double>> first = half_spectrum(x);
    for (std::size_t n = 60; n < 80; ++n) half_spectrum(series(n));
    EXPECT_EQ(half_spectrum(x), first);
}

// Each thread has its own plans: transforms on two threads at once agree with one thread's, digit for digit.
TEST(RealFft, TwoThreadsAtOnceGiveOneThreadsDigits) {
    const std::vector<double> x = series(3000), y = series(2700);
    const auto want_x = half_spectrum(x);
    const auto want_y = real_series(half_spectrum(y), y.size());
    bool same_x = true, same_y = true;
    std::thread a([&] {
        for (int i = 0; i < 50; ++i) same_x = same_x && half_spectrum(x) == want_x;
    });
    std::thread b([&] {
        for (int i = 0; i < 50; ++i) same_y = same_y && real_series(half_spectrum(y), y.size()) == want_y;
    });
    a.join();
    b.join();
    EXPECT_TRUE(same_x);
    EXPECT_TRUE(same_y);
}

}  // namespace
}  // namespace driftlab::host
