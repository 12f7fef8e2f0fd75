// Event summaries of the gap battery against closed forms: Gaussian kurtosis 3, uniform 9/5, two-point 1, and
// the block-step ratio: invariant to scale and to a random walk, large for a level jump.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "gap_fixtures.hpp"

#include "host/gap/event_statistics.hpp"

namespace driftlab::host::gap {
namespace {

using testing::white;

TEST(EventStatistics, KurtosisOfClosedFormDistributions) {
    EXPECT_NEAR(std::exp(log_kurtosis(white(200000, 3.0, 1))), 3.0, 0.05);
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> v(200000);
    for (double& x : v) x = u(rng);
    EXPECT_NEAR(std::exp(log_kurtosis(v)), 1.8, 0.02);
    // +-1 alternating: m4 = m2^2 = 1.
    std::vector<double> two(1000);
    for (std::size_t i = 0; i < two.size(); ++i) two[i] = i % 2 ? 1.0 : -1.0;
    EXPECT_NEAR(log_kurtosis(two), 0.0, 1e-12);
    EXPECT_NEAR(log_kurtosis(std::vector<double>(10, 5.0)), std::log(3.0), 1e-12);
}

TEST(EventStatistics, SpikesRaiseTheKurtosis) {
    auto y = white(4800, 1.0, 3);
    EXPECT_NEAR(std::exp(log_kurtosis(y)), 3.0, 0.25);
    for (std::size_t k = 100; k < y.size(); k += 500) y[k] += 12.0;  // 10 spikes of 12 sigma
    // m2 = 1 + 10 * 144 / 4800 = 1.3, m4 = 3 + 10 * 12^4 / 4800 = 46.2: kurtosis 46.2 / 1.69 = 27.3.
    EXPECT_NEAR(std::exp(log_kurtosis(y)), 27.3, 3.0);
}

TEST(EventStatistics, JumpRatioIsScaleFreeAndIgnoresARandomWalk) {
    const auto y = white(4800, 1.0, 4);
    std::vector<double> scaled = y;
    for (double& v : scaled) v = 7.0 * v + 100.0;
    EXPECT_NEAR(log_jump_ratio(scaled, 16), log_jump_ratio(y, 16), 1e-12);
    // A random walk has Gaussian block steps too: its ratio stays in the white-noise range (about 1.7-2.6 for
    // 15 steps), well below the bound sqrt(15) = 3.87.
    std::vector<double> walk(y.size());
    double x = 0.0;
    for (std::size_t i = 0; i < y.size(); ++i) walk[i] = x += y[i];
    EXPECT_LT(log_jump_ratio(walk, 16), std::log(3.0));
    EXPECT_LT(log_jump_ratio(y, 16), std::log(3.0));
}

TEST(EventStatistics, ALevelJumpStandsOut) {
    auto y = white(4800, 1.0, 5);
    // Block means of 300 samples have sd 1/sqrt(300) = 0.058; a step of 1 is 17 of their differences' sd (0.082)
    // against 14 ordinary steps: 12.2 / sqrt((12.2^2 + 14) / 15) = 3.7, near the bound sqrt(15) = 3.87.
    for (std::size_t k = 2100; k < y.size(); ++k) y[k] += 1.0;  // at a block boundary (7 x 300)
    EXPECT_GT(log_jump_ratio(y, 16), std::log(3.5));
    EXPECT_LE(log_jump_ratio(y, 16), std::log(std::sqrt(15.0)) + 1e-12);
    EXPECT_THROW(log_jump_ratio(y, 2), std::invalid_argument);
    EXPECT_THROW(log_jump_ratio(std::vector<double>(5, 0.0), 16), std::invalid_argument);
}

}  // namespace
}  // namespace driftlab::host::gap
