// The Nelder-Mead wrapper against closed-form minima, its evaluation budget, and its handling of bad values.
#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "host/stats/nelder_mead.hpp"

namespace driftlab::host::stats {
namespace {

TEST(NelderMead, FindsTheMinimumOfAQuadraticBowl) {
    // (x - 1.5)^2 + 4 (y + 0.25)^2 + 3: minimum 3 at (1.5, -0.25).
    auto bowl = [](const std::vector<double>& p) {
        return std::pow(p[0] - 1.5, 2) + 4.0 * std::pow(p[1] + 0.25, 2) + 3.0;
    };
    const auto r = nelder_mead(bowl, {0.0, 0.0}, {0.5, 0.5}, 200);
    EXPECT_NEAR(r.x[0], 1.5, 1e-4);
    EXPECT_NEAR(r.x[1], -0.25, 1e-4);
    EXPECT_NEAR(r.value, 3.0, 1e-8);
    EXPECT_DOUBLE_EQ(r.value, bowl(r.x));
}

TEST(NelderMead, FindsTheRosenbrockValley) {
    auto rosenbrock = [](const std::vector<double>& p) {
        return 100.0 * std::pow(p[1] - p[0] * p[0], 2) + std::pow(1.0 - p[0], 2);
    };
    const auto r = nelder_mead(rosenbrock, {-1.2, 1.0}, {0.5, 0.5}, 1000);
    EXPECT_NEAR(r.x[0], 1.0, 1e-3);
    EXPECT_NEAR(r.x[1], 1.0, 2e-3);
}

TEST(NelderMead, OneCoordinateWorks) {
    // The floor fits are one-dimensional: minimum of cosh(x - 2) at 2.
    const auto r = nelder_mead([](const std::vector<double>& p) { return std::cosh(p[0] - 2.0); }, {0.0}, {0.3}, 100);
    EXPECT_NEAR(r.x[0], 2.0, 1e-3);
}

TEST(NelderMead, KeepsToItsBudgetAndReturnsTheBestPointSeen) {
    int calls = 0;
    double best_seen = std::numeric_limits<double>::infinity();
    auto f = [&](const std::vector<double>& p) {
        ++calls;
        const double v = std::pow(p[0] - 10.0, 2) + std::pow(p[1] - 10.0, 2);
        best_seen = std::min(best_seen, v);
        return v;
    };
    const auto r = nelder_mead(f, {0.0, 0.0}, {1.0, 1.0}, 18);
    EXPECT_EQ(calls, 18);
    EXPECT_EQ(r.evaluations, 18);
    EXPECT_DOUBLE_EQ(r.value, best_seen);
    EXPECT_LT(r.value, 200.0);  // the start's value: 18 evaluations do move towards (10, 10)
}

TEST(NelderMead, NonFiniteValuesAreWorseThanAnyFiniteOne) {
    // Outside x > 0 the objective is undefined (NaN); the minimum of x - ln x is at 1.
    auto f = [](const std::vector<double>& p) { return p[0] > 0.0 ? p[0] - std::log(p[0]) : std::nan(""); };
    const auto r = nelder_mead(f, {3.0}, {-4.0}, 200);
    EXPECT_NEAR(r.x[0], 1.0, 1e-3);
    EXPECT_TRUE(std::isfinite(r.value));
    // -inf as well (a log-likelihood term of a zero spread): a failed evaluation, not the best point.
    auto g = [](const std::vector<double>& p) {
        return p[0] > 0.0 ? p[0] - std::log(p[0]) : -std::numeric_limits<double>::infinity();
    };
    const auto s = nelder_mead(g, {3.0}, {-4.0}, 200);
    EXPECT_NEAR(s.x[0], 1.0, 1e-3);
    EXPECT_TRUE(std::isfinite(s.value));
}

TEST(NelderMead, AnExceptionFromTheObjectiveReachesTheCaller) {
    int calls = 0;
    auto f = [&](const std::vector<double>& p) -> double {
        if (++calls == 5) throw std::domain_error("objective failed");
        return p[0] * p[0];
    };
    EXPECT_THROW(nelder_mead(f, {1.0}, {0.5}, 50), std::domain_error);
    EXPECT_EQ(calls, 5);
}

}  // namespace
}  // namespace driftlab::host::stats
