// Variable-projection fits recover planted two-exponential and exponential-plus-sine means.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "host/gap/mean_shapes.hpp"

namespace driftlab::host::gap {
namespace {

TEST(MeanShapes, TwoExponentialsRecoveredFromNoisyData) {
    std::mt19937_64 rng(1);
    std::normal_distribution<double> noise(0.0, 0.05);
    std::vector<double> t(3000), y(3000);
    for (std::size_t k = 0; k < t.size(); ++k) {
        t[k] = static_cast<double>(k + 1);
        y[k] = 3.0 * -std::expm1(-t[k] / 150.0) + 2.0 * -std::expm1(-t[k] / 1200.0) + 505.0 + noise(rng);
    }
    const TwoExponentials f = fit_two_exponentials(t, y, t.size());
    EXPECT_NEAR(f.t_s, 150.0, 15.0);
    EXPECT_NEAR(f.t2_s, 1200.0, 120.0);
    EXPECT_NEAR(f.c1_counts, 3.0, 0.15);
    EXPECT_NEAR(f.c3_counts, 2.0, 0.15);
    EXPECT_NEAR(f.c2_counts, 505.0, 0.05);
}

TEST(MeanShapes, SineOnTopOfWarmUpRecovered) {
    std::mt19937_64 rng(2);
    std::normal_distribution<double> noise(0.0, 0.05);
    std::vector<double> t(3000), y(3000);
    for (std::size_t k = 0; k < t.size(); ++k) {
        t[k] = static_cast<double>(k + 1);
        y[k] = 4.0 * -std::expm1(-t[k] / 300.0) + 500.0 + 0.7 * std::sin(2.0 * std::numbers::pi * t[k] / 600.0 + 1.0) +
               noise(rng);
    }
    const ExponentialAndSine f = fit_exponential_and_sine(t, y, t.size());
    EXPECT_NEAR(f.period_s, 600.0, 6.0);
    EXPECT_NEAR(f.amplitude_counts, 0.7, 0.03);
    EXPECT_NEAR(std::remainder(f.phase_rad - 1.0, 2.0 * std::numbers::pi), 0.0, 0.08);
    EXPECT_NEAR(f.t_s, 300.0, 30.0);
}

}  // namespace
}  // namespace driftlab::host::gap
