// Chi-square CDF, survival and quantile against published critical values and closed forms.
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "host/stats/chi_square.hpp"

namespace driftlab::host::stats {
namespace {

TEST(ChiSquare, SurvivalMatchesPublishedCriticalValues) {
    // Critical values of the chi-square distribution (NIST/SEMATECH e-Handbook, table 1.3.6.7.4).
    EXPECT_NEAR(chi_square_survival(3.841, 1), 0.05, 2e-5);
    EXPECT_NEAR(chi_square_survival(18.307, 10), 0.05, 2e-5);
    EXPECT_NEAR(chi_square_survival(31.410, 20), 0.05, 2e-5);
    EXPECT_NEAR(chi_square_survival(37.566, 20), 0.01, 2e-5);
    EXPECT_NEAR(chi_square_survival(124.342, 100), 0.05, 2e-5);
    EXPECT_NEAR(chi_square_survival(0.1025866, 2), 0.95, 1e-6);  // 2 ln(1/0.95)
}

TEST(ChiSquare, TwoDegreesOfFreedomAreExponentialFarIntoTheTail) {
    // Survival exp(-x/2): computed as a complement, it keeps its relative accuracy where 1 - cdf would be 0.
    for (double x : {0.01, 0.5, 3.0, 40.0, 700.0}) {
        EXPECT_NEAR(chi_square_survival(x, 2), std::exp(-x / 2), 1e-12 * std::exp(-x / 2));
        EXPECT_NEAR(chi_square_cdf(x, 2), -std::expm1(-x / 2), 1e-14);
    }
}

TEST(ChiSquare, OneDegreeOfFreedomIsASquaredNormal) {
    for (double x : {0.1, 1.0, 2.5, 10.0}) EXPECT_NEAR(chi_square_cdf(x, 1), std::erf(std::sqrt(x / 2)), 1e-14);
}

TEST(ChiSquare, QuantileInvertsTheCdfInBothTailsForFractionalDof) {
    for (double dof : {0.7, 1.0, 3.3, 47.5, 1e4}) {
        for (double p : {1e-9, 0.025, 0.5, 0.975, 1.0 - 1e-9}) {
            const double x = chi_square_quantile(p, dof);
            if (p > 0.5)
                EXPECT_NEAR(chi_square_survival(x, dof), 1.0 - p, 1e-11 * (1.0 - p)) << dof << " " << p;
            else
                EXPECT_NEAR(chi_square_cdf(x, dof), p, 1e-11 * p) << dof << " " << p;
        }
    }
    EXPECT_NEAR(chi_square_quantile(0.95, 10), 18.307038, 1e-6);
}

TEST(ChiSquare, RefusesValuesOutsideTheDomain) {
    EXPECT_THROW(chi_square_quantile(0.0, 3.0), std::invalid_argument);
    EXPECT_THROW(chi_square_quantile(1.0, 3.0), std::invalid_argument);
    EXPECT_THROW(chi_square_quantile(0.5, 0.0), std::invalid_argument);
    EXPECT_THROW(chi_square_survival(1.0, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace driftlab::host::stats
