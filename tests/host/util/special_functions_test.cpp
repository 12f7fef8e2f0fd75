// Special functions against published table values and closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "host/util/special_functions.hpp"

namespace driftlab::host {
namespace {

TEST(SpecialFunctions, ChiSquareSurvivalMatchesPublishedCriticalValues) {
    // Critical values of the chi-square distribution (NIST/SEMATECH e-Handbook, table 1.3.6.7.4).
    EXPECT_NEAR(chi_square_survival(3.841, 1), 0.05, 2e-5);
    EXPECT_NEAR(chi_square_survival(18.307, 10), 0.05, 2e-5);
    EXPECT_NEAR(chi_square_survival(31.410, 20), 0.05, 2e-5);
    EXPECT_NEAR(chi_square_survival(37.566, 20), 0.01, 2e-5);
    EXPECT_NEAR(chi_square_survival(124.342, 100), 0.05, 2e-5);
    EXPECT_NEAR(chi_square_survival(0.1025866, 2), 0.95, 1e-6);  // 2 ln(1/0.95)
}

TEST(SpecialFunctions, ChiSquareWithTwoDofIsExponential) {
    for (double x : {0.01, 0.5, 3.0, 40.0, 700.0}) EXPECT_NEAR(chi_square_survival(x, 2), std::exp(-x / 2), 1e-13 + 1e-12 * std::exp(-x / 2));
}

TEST(SpecialFunctions, GammaPAndQAddToOneAndMatchErf) {
    for (double x : {0.1, 1.0, 2.5, 10.0}) {
        EXPECT_NEAR(regularized_gamma_p(0.5, x), std::erf(std::sqrt(x)), 1e-13);
        EXPECT_NEAR(regularized_gamma_p(3.7, x) + regularized_gamma_q(3.7, x), 1.0, 1e-14);
    }
}

TEST(SpecialFunctions, StudentTQuantilesMatchTables) {
    // Two-sided 95 % points (t_{0.975}): 12.706 (1), 2.228 (10), 2.042 (30), 1.984 (100), 1.960 (inf).
    EXPECT_NEAR(student_t_quantile(0.975, 1), 12.7062047, 1e-6);
    EXPECT_NEAR(student_t_quantile(0.975, 10), 2.2281389, 1e-6);
    EXPECT_NEAR(student_t_quantile(0.975, 30), 2.0422725, 1e-6);
    EXPECT_NEAR(student_t_quantile(0.975, 100), 1.9839715, 1e-6);
    EXPECT_NEAR(student_t_quantile(0.975, 1e8), 1.9599640, 1e-6);
    EXPECT_NEAR(student_t_quantile(0.025, 10), -2.2281389, 1e-6);
    // dof = 1 is Cauchy: quantile tan(pi (p - 1/2)).
    EXPECT_NEAR(student_t_quantile(0.9, 1), std::tan(M_PI * 0.4), 1e-9);
}

TEST(SpecialFunctions, IncompleteBetaClosedForms) {
    for (double x : {0.0, 0.2, 0.5, 0.9, 1.0}) {
        EXPECT_NEAR(regularized_beta(1.0, 1.0, x), x, 1e-14);
        EXPECT_NEAR(regularized_beta(2.0, 1.0, x), x * x, 1e-14);
        EXPECT_NEAR(regularized_beta(1.0, 3.0, x), 1.0 - std::pow(1.0 - x, 3), 1e-14);
    }
}

}  // namespace
}  // namespace driftlab::host
