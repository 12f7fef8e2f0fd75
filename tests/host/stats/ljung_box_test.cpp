// Ljung–Box statistic and p-value against hand-computed values and chi-square critical points.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "host/stats/ljung_box.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::stats {
namespace {

TEST(LjungBox, AlternatingSeriesMatchesTheHandComputation) {
    // w = +1,-1,... (n = 10): biased rho(1) = -9/10. Q = n (n+2) rho1^2 / (n-1) = 10 * 12 * 0.81 / 9 = 10.8;
    // chi2(1) survival of 10.8 = erfc(sqrt(10.8/2)) = 0.0010150.
    const std::vector<double> rho = {1.0, -0.9};
    const LjungBoxResult r = ljung_box(rho, 10, 1);
    EXPECT_NEAR(r.statistic, 10.8, 1e-12);
    EXPECT_NEAR(r.p_value, std::erfc(std::sqrt(5.4)), 1e-12);
    EXPECT_NEAR(r.p_value, 0.0010150, 1e-6);
}

TEST(LjungBox, StatisticAtTheCriticalValueGivesFivePercent) {
    // Choose rho so Q equals the tabulated 95 % point of chi2(h): 3.841 (h = 1), 18.307 (h = 10).
    const std::size_t n = 200;
    const double nd = static_cast<double>(n);
    {
        const std::vector<double> rho = {1.0, std::sqrt(3.841 * (nd - 1) / (nd * (nd + 2)))};
        const LjungBoxResult r = ljung_box(rho, n, 1);
        EXPECT_NEAR(r.statistic, 3.841, 1e-9);
        EXPECT_NEAR(r.p_value, 0.05, 1e-4);
    }
    {
        // Equal contributions from 10 lags.
        std::vector<double> rho = {1.0};
        for (std::size_t k = 1; k <= 10; ++k)
            rho.push_back(std::sqrt(18.307 / 10 * (nd - static_cast<double>(k)) / (nd * (nd + 2))));
        const LjungBoxResult r = ljung_box(rho, n, 10);
        EXPECT_NEAR(r.statistic, 18.307, 1e-9);
        EXPECT_NEAR(r.p_value, 0.05, 1e-4);
        const LjungBoxResult fitted = ljung_box(rho, n, 10, 2);  // 8 dof: 95 % point 15.507 < 18.307
        EXPECT_EQ(fitted.dof, 8.0);
        EXPECT_LT(fitted.p_value, 0.05);
    }
}

TEST(LjungBox, DefaultLagsAndBadArguments) {
    EXPECT_EQ(default_ljung_box_lags(1000), 20u);
    EXPECT_EQ(default_ljung_box_lags(50), 10u);
    EXPECT_EQ(default_ljung_box_lags(3), 1u);
    EXPECT_THROW(ljung_box({1.0, 0.1}, 10, 2), UsageError);  // fewer rho values than lags
    EXPECT_THROW(ljung_box({1.0, 0.1}, 1, 1), UsageError);   // lags >= n
}

}  // namespace
}  // namespace driftlab::host::stats
