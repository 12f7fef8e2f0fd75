// Clopper-Pearson against closed forms at the ends (k = 0: upper = 1 - (alpha/2)^(1/n)) and published values.
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "host/stats/binomial_interval.hpp"

namespace driftlab::host::stats {
namespace {

TEST(ClopperPearson, EndsHaveClosedForms) {
    const auto none = clopper_pearson(0, 10);
    EXPECT_EQ(none.lower, 0.0);
    EXPECT_NEAR(none.upper, 1.0 - std::pow(0.025, 0.1), 1e-12);
    const auto all = clopper_pearson(20, 20);
    EXPECT_NEAR(all.lower, std::pow(0.025, 1.0 / 20.0), 1e-12);
    EXPECT_EQ(all.upper, 1.0);
}

TEST(ClopperPearson, MatchesPublishedIntervals) {
    // 5 of 10 at 95 %: [0.1871, 0.8129] (Clopper & Pearson 1934 tables; R binom.test).
    const auto half = clopper_pearson(5, 10);
    EXPECT_NEAR(half.lower, 0.18709, 5e-5);
    EXPECT_NEAR(half.upper, 0.81291, 5e-5);
    // 1 of 100: [0.000253, 0.05446].
    const auto rare = clopper_pearson(1, 100);
    EXPECT_NEAR(rare.lower, 0.000253, 2e-6);
    EXPECT_NEAR(rare.upper, 0.05446, 5e-5);
}

TEST(ClopperPearson, RejectsImpossibleCounts) {
    EXPECT_THROW(clopper_pearson(0, 0), std::invalid_argument);
    EXPECT_THROW(clopper_pearson(3, 2), std::invalid_argument);
    EXPECT_THROW(clopper_pearson(1, 2, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace driftlab::host::stats
