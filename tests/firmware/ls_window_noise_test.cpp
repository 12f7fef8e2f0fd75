// LsWindow on white noise: the variance of its output matches least-squares theory within 3 %.
//   order 0:                   var = sigma^2 / N
//   order 1 at the newest x:   var = sigma^2 * 2 (2N - 1) / (N (N + 1))
// Outputs are taken from non-overlapping windows (one every N pushes), so they are independent and the sample
// variance of M of them has a relative standard error of about sqrt(2 / M); M = 40000 puts 3 % beyond 4 sigma.
#include "firmware/core/ls_window.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>

namespace driftlab {
namespace fw {
namespace {

// Integer white noise with an exactly known variance: uniform on 512 +- kHalfWidth, variance ((2a+1)^2 - 1)/12.
constexpr int kHalfWidth = 100;
constexpr double kSigma2Counts2 = ((2.0 * kHalfWidth + 1.0) * (2.0 * kHalfWidth + 1.0) - 1.0) / 12.0;
constexpr int kOutputs = 40000;

double theory_variance(int window, FitOrder order) {
  const double n = window;
  return order == FitOrder::mean ? kSigma2Counts2 / n : kSigma2Counts2 * 2.0 * (2.0 * n - 1.0) / (n * (n + 1.0));
}

double output_variance(uint8_t window, FitOrder order, uint32_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> code(512 - kHalfWidth, 512 + kHalfWidth);
  LsWindow lsw;
  lsw.reset(window);
  double sum = 0.0;
  double sum_sq = 0.0;
  for (int m = 0; m < kOutputs; ++m) {
    for (int k = 0; k < window; ++k) {
      lsw.push(static_cast<uint16_t>(code(rng)));
    }
    const double v = lsw.estimate_q8(order) / 256.0;
    sum += v;
    sum_sq += v * v;
  }
  const double mean = sum / kOutputs;
  return (sum_sq - kOutputs * mean * mean) / (kOutputs - 1);
}

TEST(LsWindowNoise, OutputVarianceMatchesTheoryWithinThreePercent) {
  uint32_t seed = 1;
  for (uint8_t window : {uint8_t{1}, uint8_t{2}, uint8_t{3}, uint8_t{8}, uint8_t{16}, uint8_t{25}, uint8_t{64}}) {
    for (FitOrder order : {FitOrder::mean, FitOrder::line}) {
      const double expected = theory_variance(window, order);
      const double got = output_variance(window, order, seed++);
      EXPECT_NEAR(got / expected, 1.0, 0.03)
          << "window " << int(window) << " order " << int(order) << ": variance " << got << " vs " << expected;
    }
  }
}

}  // namespace
}  // namespace fw
}  // namespace driftlab
