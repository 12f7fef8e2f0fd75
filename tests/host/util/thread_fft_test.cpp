// The half spectrum against a direct DFT, and the shared FFT object left whole after it.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "host/util/thread_fft.hpp"

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

// Lengths that take each of the transform's paths: a multiple of four (the real transform at half length), even but
// not a multiple of four, odd (both through the complex transform), and one point (no transform).
TEST(ThreadFft, TheHalfSpectrumHoldsTheBinsUpToNyquistOfADirectTransform) {
    for (std::size_t n : {96u, 98u, 75u, 1u}) {
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

TEST(ThreadFft, NoSamplesHaveNoBins) { EXPECT_TRUE(half_spectrum({}).empty()); }

TEST(ThreadFft, AWholeTransformAfterAHalfSpectrumIsWholeAndAgreesWithIt) {
    const std::vector<double> x = series(98);
    const std::vector<std::complex<double>> half = half_spectrum(x);
    std::vector<std::complex<double>> whole;
    thread_fft().fwd(whole, x);
    ASSERT_EQ(whole.size(), x.size());
    for (std::size_t k = 0; k < half.size(); ++k) EXPECT_EQ(whole[k], half[k]) << "bin " << k;
    for (std::size_t k = 1; k < x.size() / 2; ++k) EXPECT_EQ(whole[x.size() - k], std::conj(whole[k])) << "bin " << k;
}

}  // namespace
}  // namespace driftlab::host
