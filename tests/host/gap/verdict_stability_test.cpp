// The estimates' spread over the stability logs: sample quantiles (linear between order statistics, the
// "type 7" definition) and the lines the terminal, the report and the model file share.
#include <cmath>

#include <gtest/gtest.h>

#include "host/gap/verdict_stability.hpp"

namespace driftlab::host::gap {
namespace {

TEST(ParameterSpread, QuantilesInterpolateBetweenOrderStatistics) {
    ParameterSpread p{"gauss_markov", "gyro", "tau_s", 20.0, {10.0, 20.0, 30.0, 40.0, 50.0}};
    EXPECT_DOUBLE_EQ(p.quantile(0.0), 10.0);
    EXPECT_DOUBLE_EQ(p.quantile(1.0), 50.0);
    EXPECT_DOUBLE_EQ(p.quantile(0.5), 30.0);
    EXPECT_DOUBLE_EQ(p.quantile(0.16), 16.4);  // position 0.64 between 10 and 20
    EXPECT_DOUBLE_EQ(p.quantile(0.84), 43.6);  // position 3.36 between 40 and 50
    EXPECT_TRUE(std::isnan(ParameterSpread{}.quantile(0.5)));
}

TEST(ParameterSpread, EachAddedEffectGetsOneLineAndOneNotFoundAgainSaysSo) {
    VerdictStability s;
    s.logs = 4;
    s.params = {{"gauss_markov", "gyro", "sigma_dps", 0.02, {0.01, 0.02, 0.03}, 3},
                {"gauss_markov", "gyro", "tau_s", 20.0, {10.0, 20.0, 30.0}, 3},
                {"thermal_second_tc", "gyro", "c3_dps", -0.3, {}, 0},
                {"thermal_second_tc", "gyro", "t2_s", 12000.0, {}, 0},
                // A DNL table's transitions differ from log to log: 507 is not found again, 508 in 2 of the 3 logs.
                {"adc_dnl", "gyro", "t507_counts", 507.4, {}, 3},
                {"adc_dnl", "gyro", "t508_counts", 508.6, {508.5, 508.7}, 3}};
    const std::vector<std::string> lines = spread_lines(s);
    ASSERT_EQ(lines.size(), 3u);
    // Each value to the digits half its middle 68 % warrants (%.3g had made 508.532 to 508.668 "509 to 509"): sigma's
    // half-width 0.0068 puts the last digit at 1e-4, tau's 6.8 at 0.1, the transition's 0.068 at 1e-3. Without a
    // spread, four significant digits and no exponent (t2_s had read 1.2e+04).
    EXPECT_EQ(lines[0],
              "gauss_markov on gyro (3 of 4 logs): sigma_dps 0.0200 -> 0.0132 to 0.0268 (median 0.0200); "
              "tau_s 20.0 -> 13.2 to 26.8 (median 20.0)");
    EXPECT_EQ(lines[1], "thermal_second_tc on gyro: added again in none of the 4 logs (c3_dps -0.3, t2_s 12000)");
    EXPECT_EQ(lines[2],
              "adc_dnl on gyro (3 of 4 logs): t507_counts 507.4 -> not found again; t508_counts 508.600 -> 508.532 to "
              "508.668 (median 508.600) in 2");
}

}  // namespace
}  // namespace driftlab::host::gap
