// How far from its batch a board must lie to stand out; see standout_limit.hpp.
#include "host/fleet/standout_limit.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "host/stats/median.hpp"

namespace driftlab::host::fleet {
namespace {

// max_i |x_i - median| / (1.4826 MAD) of one batch.
double largest_z(const std::vector<double>& x) {
    const double centre = stats::median(x);
    std::vector<double> deviation(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) deviation[i] = std::fabs(x[i] - centre);
    const double largest = *std::max_element(deviation.begin(), deviation.end());
    const double scale = kMadToSigma * stats::median(std::move(deviation));
    return scale > 0.0 ? largest / scale : INFINITY;
}

}  // namespace

double standout_limit(std::size_t boards, std::size_t parameters) {
    const double tail = kFalseStandout / static_cast<double>(std::max<std::size_t>(parameters, 1));
    // About 40 batches beyond the quantile, and no more than 5e7 draws for a fleet of thousands.
    const auto wanted = static_cast<std::size_t>(std::ceil(40.0 / tail));
    const std::size_t trials = std::clamp<std::size_t>(wanted, 2000, std::max<std::size_t>(2000, 50'000'000 / boards));
    std::mt19937_64 rng(20261207);
    std::normal_distribution<double> normal;
    std::vector<double> largest(trials), x(boards);
    for (double& z : largest) {
        for (double& v : x) v = normal(rng);
        z = largest_z(x);
    }
    const auto k = static_cast<std::size_t>(std::floor((1.0 - tail) * static_cast<double>(trials - 1)));
    std::nth_element(largest.begin(), largest.begin() + static_cast<std::ptrdiff_t>(k), largest.end());
    return largest[k];
}

}  // namespace driftlab::host::fleet
