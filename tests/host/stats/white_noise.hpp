// Gaussian white noise for the tests that need a known spectrum or deviation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace driftlab::host::testing {

/// n Gaussian samples of standard deviation sigma.
inline std::vector<double> white(std::size_t n, double sigma, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> d(0.0, sigma);
    std::vector<double> v(n);
    for (double& x : v) x = d(rng);
    return v;
}

}  // namespace driftlab::host::testing
