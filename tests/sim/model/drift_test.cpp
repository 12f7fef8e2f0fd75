// Eq. 1 of the paper and Table 1 as the defaults.
#include "sim/model/drift.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace driftlab::sim {
namespace {

TEST(Drift, FollowsEquationOneAtEveryTime) {
    const Drift d({3.0, 505.0, 411.0});
    for (double t : {0.0, 1.0, 10.0, 100.0, 411.0, 1000.0, 4000.0}) {
        EXPECT_NEAR(d.at_counts(t), 3.0 * (1.0 - std::exp(-t / 411.0)) + 505.0, 1e-12) << t;
    }
}

TEST(Drift, StartsAtC2ReachesOneMinusOneOverEAtTauAndSettlesAtC1PlusC2) {
    const Drift d({28.0, 622.0, 1050.0});
    EXPECT_DOUBLE_EQ(d.at_counts(0.0), 622.0);
    EXPECT_NEAR(d.at_counts(1050.0), 622.0 + 28.0 * (1.0 - 1.0 / M_E), 1e-12);
    EXPECT_NEAR(d.at_counts(1e6), 650.0, 1e-12);
}

TEST(Drift, DefaultsAreTableOneOfThePaper) {
    const double table1[4][3] = {{3, 505, 411}, {2, 470, 953}, {23, 474, 937}, {28, 622, 1050}};
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        EXPECT_EQ(kPaperDrift[c].c1_counts, table1[c][0]) << kChannelNames[c];
        EXPECT_EQ(kPaperDrift[c].c2_counts, table1[c][1]) << kChannelNames[c];
        EXPECT_EQ(kPaperDrift[c].tau_s, table1[c][2]) << kChannelNames[c];
    }
}

}  // namespace
}  // namespace driftlab::sim
