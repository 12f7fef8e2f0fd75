// Variable-projection fits recover planted two-exponential and exponential-plus-sine means.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

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

// Eq. 1 with two level steps: where the log is exactly that (T on the profile's grid), nothing is left; with noise
// added, the residual is least squares, so orthogonal to the constant and to both step columns.
TEST(MeanShapes, Eq1AndStepsResidualIsLeastSquaresAndExactOnItsOwnForm) {
    std::vector<double> t(1500), y(1500);
    const double span = 1499.0, tau = 0.003 * span * std::pow(1.2, 30);  // on the grid: about 356 s
    for (std::size_t k = 0; k < t.size(); ++k) {
        t[k] = static_cast<double>(k);
        y[k] = -40.0 * (1.0 - std::exp(-t[k] / tau)) + 512.0 + (k >= 500 ? 1.5 : 0.0) + (k >= 1100 ? -0.9 : 0.0);
    }
    for (double e : eq1_and_steps_residual(t, y, 500, 1100)) EXPECT_NEAR(e, 0.0, 1e-8);
    std::mt19937_64 rng(3);
    std::normal_distribution<double> noise(0.0, 0.4);
    for (double& v : y) v += noise(rng);
    const std::vector<double> e = eq1_and_steps_residual(t, y, 500, 1100);
    double all = 0.0, after1 = 0.0, after2 = 0.0, ss = 0.0;
    for (std::size_t k = 0; k < e.size(); ++k) {
        all += e[k], ss += e[k] * e[k];
        if (k >= 500) after1 += e[k];
        if (k >= 1100) after2 += e[k];
    }
    EXPECT_NEAR(all, 0.0, 1e-8);
    EXPECT_NEAR(after1, 0.0, 1e-8);
    EXPECT_NEAR(after2, 0.0, 1e-8);
    EXPECT_NEAR(std::sqrt(ss / static_cast<double>(e.size())), 0.4, 0.03);  // what is left is the noise
}

}  // namespace
}  // namespace driftlab::host::gap
