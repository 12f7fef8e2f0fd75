// What the truth generator tests share: gap-eval's output grid and a mean.
#pragma once

#include <cstddef>
#include <numeric>
#include <vector>

namespace driftlab::host::gap::truth_testing {

inline constexpr double kPi = 3.14159265358979323846;

// gap-eval's grid: 1500 outputs at 1 s, from t = 1 s (evaluate.cpp).
inline std::vector<double> eval_grid(std::size_t n = 1500) {
    std::vector<double> t(n);
    for (std::size_t k = 0; k < n; ++k) t[k] = static_cast<double>(k + 1);
    return t;
}

inline double mean_of(const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

}  // namespace driftlab::host::gap::truth_testing
