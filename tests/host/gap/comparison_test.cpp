// The max-|z| threshold controls the family-wise flag rate, and the gap score is about 1 under the null.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "host/gap/comparison.hpp"

namespace driftlab::host::gap {
namespace {

struct NullRates {
    double flagged = 0.0;     ///< fraction of trials with a located cell
    double score = 0.0;       ///< mean gap score
    double score_over = 0.0;  ///< fraction of trials whose gap score exceeds its bound
};

// Null logs drawn like the replicates: 60 correlated cells (an AR(1) along the cells, like neighbouring octaves).
NullRates null_rates(int r, int trials, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> n01;
    const int cells = 60;
    auto draw = [&] {
        std::vector<double> v(cells);
        double x = n01(rng);
        for (int j = 0; j < cells; ++j) {
            x = 0.6 * x + 0.8 * n01(rng);
            v[static_cast<std::size_t>(j)] = 3.0 + 0.5 * x;
        }
        return v;
    };
    std::vector<Cell> layout(cells);
    const auto all = [](const Cell&) { return true; };
    NullRates out;
    for (int t = 0; t < trials; ++t) {
        Eigen::MatrixXd reps(r, cells);
        for (int i = 0; i < r; ++i) {
            const auto v = draw();
            for (int j = 0; j < cells; ++j) reps(i, j) = v[static_cast<std::size_t>(j)];
        }
        const auto real = draw();
        const Comparison cmp = compare(real, reps, 0.05);
        const double score = gap_score(cmp, layout, all);
        out.flagged += locate(real, cmp, layout).empty() ? 0.0 : 1.0 / trials;
        out.score += score / trials;
        out.score_over += score > gap_score_threshold(cmp, layout, all, 0.05) ? 1.0 / trials : 0.0;
    }
    return out;
}

// Monte Carlo tests at level alpha: the real log, exchangeable with the R replicates, exceeds the max-|z| threshold
// and the gap-score bound in alpha of the trials, whatever R (19 = the smallest R for which alpha = 5 % is exact,
// 40 = the default).
TEST(Comparison, ThresholdsFlagAlphaOfNullLogs) {
    for (const int r : {19, 40}) {
        const NullRates n = null_rates(r, 3000, 11u + static_cast<unsigned>(r));
        // Binomial sd at 5 % over 3000 trials is 0.4 %.
        EXPECT_GT(n.flagged, 0.035) << "R = " << r;
        EXPECT_LT(n.flagged, 0.065) << "R = " << r;
        EXPECT_GT(n.score_over, 0.025) << "R = " << r;  // a little conservative: left-out z are wider
        EXPECT_LT(n.score_over, 0.065) << "R = " << r;
        EXPECT_NEAR(n.score, 1.0, 0.05) << "R = " << r;
    }
}

TEST(Comparison, ShiftedCellIsLocatedWithItsSignAndRatio) {
    std::mt19937_64 rng(5);
    std::normal_distribution<double> n01;
    const int cells = 20, r = 30;
    Eigen::MatrixXd reps(r, cells);
    for (int i = 0; i < r; ++i)
        for (int j = 0; j < cells; ++j) reps(i, j) = n01(rng) * 0.1;
    std::vector<double> real(cells, 0.0);
    real[7] = std::log(2.0);  // a doubled deviation
    std::vector<Cell> layout(cells);
    for (auto& c : layout) c.log_scale = true, c.margin = 0.0953;
    const Comparison cmp = compare(real, reps, 0.05);
    const auto located = locate(real, cmp, layout);
    ASSERT_EQ(located.size(), 1u);
    EXPECT_EQ(located[0].index, 7u);
    EXPECT_GT(located[0].z, 3.0);
    EXPECT_NEAR(located[0].ratio, 2.0 * std::exp(-cmp.sim_mean[7]), 1e-9);
    // The interval is the ratio times exp(+-1.96 sd) of the replicates (about 0.1 here).
    EXPECT_NEAR(located[0].interval_low, located[0].ratio * std::exp(-1.96 * cmp.sim_sd[7]), 1e-9);
    EXPECT_NEAR(located[0].interval_high, located[0].ratio * std::exp(1.96 * cmp.sim_sd[7]), 1e-9);
    EXPECT_LT(located[0].interval_low, located[0].ratio);
}

TEST(Comparison, LargeButIrrelevantDifferenceIsNotLocated) {
    // Significant (tiny spread) but below the practical margin: not a gap.
    std::mt19937_64 rng(6);
    std::normal_distribution<double> n01;
    Eigen::MatrixXd reps(30, 5);
    for (int i = 0; i < 30; ++i)
        for (int j = 0; j < 5; ++j) reps(i, j) = 1e-4 * n01(rng);
    std::vector<double> real(5, 0.0);
    real[2] = 0.05;
    std::vector<Cell> layout(5);
    for (auto& c : layout) c.margin = 0.1;
    const Comparison cmp = compare(real, reps, 0.05);
    EXPECT_GT(std::abs(cmp.z[2]), 50.0);
    EXPECT_TRUE(locate(real, cmp, layout).empty());
}

}  // namespace
}  // namespace driftlab::host::gap

namespace driftlab::host::gap {
namespace {

// Replicates that all agree (a lossless link: every replicate loses nothing): a log that agrees scores 1, one that
// differs scores its own mean z^2 against the per-cell floor, not the 1 a zero null would otherwise give.
TEST(Comparison, ReplicatesThatAllAgreeScoreTheLogsOwnDifference) {
    const Eigen::MatrixXd replicates = Eigen::MatrixXd::Zero(20, 2);
    const std::vector<Cell> layout{{"loss", "link", -1, "a", Segment::heldout, false, 1e-3},
                                   {"burst", "link", -1, "b", Segment::heldout, false, 0.5}};
    const auto all = [](const Cell&) { return true; };
    const std::vector<double> floors{0.01, 0.1};
    EXPECT_DOUBLE_EQ(gap_score(compare({0.0, 0.0}, replicates, 0.05, &floors), layout, all), 1.0);
    const Comparison lossy = compare({0.03, 2.0}, replicates, 0.05, &floors);
    EXPECT_DOUBLE_EQ(lossy.z[0], 3.0);   // 0.03 over the floor 0.01
    EXPECT_DOUBLE_EQ(lossy.z[1], 20.0);  // 2 frames over 0.1
    EXPECT_DOUBLE_EQ(gap_score(lossy, layout, all), (9.0 + 400.0) / 2.0);
    EXPECT_EQ(locate({0.03, 2.0}, lossy, layout).size(), 2u);
}

}  // namespace
}  // namespace driftlab::host::gap
