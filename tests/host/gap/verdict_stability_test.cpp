// The estimates' spread over the stability logs: sample quantiles (linear between order statistics, the
// "type 7" definition).
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

}  // namespace
}  // namespace driftlab::host::gap
