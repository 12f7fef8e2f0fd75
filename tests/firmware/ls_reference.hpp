// Double-precision least-squares reference for LsWindow tests: fits a polynomial of order 0 or 1 to samples at
// x = 0..n-1 by centred normal equations and evaluates it at the newest point x = n-1. Independent of the
// firmware's running sums and integer formula.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>

namespace driftlab {
namespace fw {
namespace test {

/// LS value at the newest of `samples` [counts]; order 1 with one sample degenerates to that sample.
inline double ls_reference(const std::deque<uint16_t>& samples, int order) {
  const std::size_t n = samples.size();
  double mean_x = 0.0;
  double mean_y = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    mean_x += static_cast<double>(i);
    mean_y += samples[i];
  }
  mean_x /= static_cast<double>(n);
  mean_y /= static_cast<double>(n);
  if (order == 0 || n < 2) {
    return mean_y;
  }
  double sxy = 0.0;
  double sxx = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = static_cast<double>(i) - mean_x;
    sxy += dx * (samples[i] - mean_y);
    sxx += dx * dx;
  }
  const double slope = sxy / sxx;
  return mean_y + slope * (static_cast<double>(n - 1) - mean_x);
}

}  // namespace test
}  // namespace fw
}  // namespace driftlab
