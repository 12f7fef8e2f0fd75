// The level-step test: a hop and a return planted on top of a random walk are found where and about as large as they
// were planted, and read as the walk's outsized increments (the walk is there beside them); the same hop on the white
// floor, which the walk only stands in for, is a step no library effect makes; the random walk alone passes.
#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "gap_fixtures.hpp"
#include "host/gap/candidates.hpp"
#include "host/gap/level_step.hpp"
#include "host/gap/mean_shapes.hpp"
#include "host/gap/whittle.hpp"

namespace driftlab::host::gap {
namespace {

constexpr double kWalk = 0.002;  // deg/s per sqrt(s): a walk of about 1 count over the log

GapModel walk_model() {
    GapModel m = testing::paper_gyro_model(8);
    m.effects.push_back(make_candidate_effect("rate_random_walk", Channel::gyro, {kWalk}, m));
    return m;
}

LevelStep run(const GapModel& m, const std::vector<double>& added, std::uint64_t seed) {
    const LogData log = testing::gyro_log(m, 2000, added, seed);
    return test_level_step(m, Channel::gyro, log.t_s, log.counts[0], {"rate_random_walk"}, {kWalk}, 40, 9, 2, 0.05);
}

std::vector<double> hop_and_return() {
    std::vector<double> hop(2000, 0.0);
    for (std::size_t k = 700; k < 1400; ++k) hop[k] = 1.5;  // counts: up at t = 700.5 s, back at 1400.5 s
    return hop;
}

TEST(LevelStep, AHopAndReturnOnARandomWalkAreFoundWhereAndAsLargeAsTheyWereAndReadAsItsIncrements) {
    const std::vector<double> hop = hop_and_return();
    for (std::uint64_t seed : {31, 32, 33, 34, 35}) {
        const LevelStep s = run(walk_model(), hop, seed);
        EXPECT_LE(s.p_value, 0.05) << "seed " << seed << " statistic " << s.statistic;
        EXPECT_GT(s.statistic, s.margin) << "seed " << seed;
        // The walk (about 1 count over the log) is still there once the steps are out: its Whittle gain over the
        // floor beside them exceeds the Schwarz price of its one parameter, so the steps are its outsized increments.
        EXPECT_GT(s.process_gain, s.process_margin) << "seed " << seed;
        EXPECT_NEAR(s.process_margin, 0.5 * std::log(1999.0), 0.1) << "seed " << seed;
        EXPECT_TRUE(s.outsized) << "seed " << seed;
        EXPECT_FALSE(s.significant) << "seed " << seed;
        EXPECT_NE(std::string(step_reading(s)).find("outsized increments"), std::string::npos) << step_reading(s);
        // The larger first; either may be the up or the down step.
        const bool up_first = s.steps[0].size_counts > 0.0;
        const StepEstimate& up = s.steps[up_first ? 0 : 1];
        const StepEstimate& down = s.steps[up_first ? 1 : 0];
        EXPECT_NEAR(up.t_s, 700.5, 20.0) << "seed " << seed;
        EXPECT_NEAR(down.t_s, 1400.5, 20.0) << "seed " << seed;
        EXPECT_NEAR(up.size_counts, 1.5, 0.5) << "seed " << seed;
        EXPECT_NEAR(down.size_counts, -1.5, 0.5) << "seed " << seed;
    }
}

// The same hop on the white floor, explained by the walk: once two steps (and eq. 1) are fitted, nothing is left for
// the walk, whose gain over the floor is then the chance gain of a nested parameter at its boundary (half a chi^2_1:
// P(gain > ln(n) / 2) is about 0.3 %), so the step is one no library effect makes.
TEST(LevelStep, AHopOnTheWhiteFloorThatAWalkStandsInForIsAStepNoLibraryEffectMakes) {
    const std::vector<double> hop = hop_and_return();
    for (std::uint64_t seed : {31, 32, 33}) {
        const LogData log = testing::gyro_log(testing::paper_gyro_model(8), 2000, hop, seed);
        const LevelStep s = test_level_step(walk_model(), Channel::gyro, log.t_s, log.counts[0], {"rate_random_walk"},
                                            {kWalk}, 40, 9, 2, 0.05);
        EXPECT_LE(s.process_gain, s.process_margin) << "seed " << seed;
        EXPECT_FALSE(s.process_beside_steps) << "seed " << seed;
        EXPECT_TRUE(s.significant) << "seed " << seed << " p " << s.p_value;
        EXPECT_FALSE(s.outsized) << "seed " << seed;
        EXPECT_NE(std::string(step_reading(s)).find("no library effect makes"), std::string::npos) << step_reading(s);
    }
}

// A hop in eq. 1's warm-up bends the eq. 1 fit toward it; change points placed on that fit's residual alone took
// the bend's remainder near the start for the second step and left the half return at 1100 s for the walk (gain
// above its price in 5 of these 16 logs, up to 6.6). Placed beside eq. 1's tangent, the two steps leave the walk
// nothing to take up.
TEST(LevelStep, AHopInTheWarmUpLeavesNoProcessBesideItsSteps) {
    constexpr double kSlightWalk = 0.001;
    GapModel m = testing::paper_gyro_model(8);
    m.effects.push_back(make_candidate_effect("rate_random_walk", Channel::gyro, {kSlightWalk}, m));
    std::vector<double> hop(1500, 0.0);
    for (std::size_t k = 300; k < hop.size(); ++k) hop[k] = k < 1100 ? 0.3 : 0.15;  // counts: up at 300 s, half back
    double total_gain = 0.0;
    for (std::uint64_t seed = 1; seed <= 16; ++seed) {
        const LogData log = testing::gyro_log(testing::paper_gyro_model(8), hop.size(), hop, seed);
        const LevelStep s = test_level_step(m, Channel::gyro, log.t_s, log.counts[0], {"rate_random_walk"},
                                            {kSlightWalk}, 40, 9, 2, 0.05);
        EXPECT_FALSE(s.process_beside_steps)
            << "seed " << seed << ": gain " << s.process_gain << " against " << s.process_margin;
        total_gain += s.process_gain;
    }
    EXPECT_LT(total_gain / 16.0, 0.5) << "the nested gain of a process that is not there is about 0";
}

// The Monte Carlo part is a level-alpha test: of eight logs from the model itself at most two may be flagged
// (binomial, 5 %: probability 0.6 %; the likelihood margin only lowers the rate).
TEST(LevelStep, TheModelsOwnLogsPass) {
    int flagged = 0;
    for (std::uint64_t seed = 41; seed < 49; ++seed) {
        const LevelStep s = run(walk_model(), {}, seed);
        flagged += s.significant;
        if (!s.significant && !s.outsized) {
            EXPECT_STREQ(step_reading(s), "none beyond the model's own");
        }
    }
    EXPECT_LE(flagged, 2);
}

// Two correlated statistics and the rival's margin at its 70th percentile, as under the explanation: the combined p
// of a draw from the replicates' own distribution is uniform on the ranks (an exact test: P(p <= 0.05) = 4/80 with
// 79 replicates), and it lies between the smaller p and Bonferroni's twice that.
TEST(LevelStep, TheCombinedPIsAnExactMonteCarloTest) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> normal;
    const auto draw = [&] {
        const double a = normal(rng);
        return std::array<double, 2>{a, 0.6 * a + 0.8 * normal(rng)};
    };
    constexpr int kReplicates = 79, kTrials = 4000;
    const double margin = 0.524;  // the standard normal's 70th percentile
    int rejected = 0;
    for (int trial = 0; trial < kTrials; ++trial) {
        Eigen::MatrixXd null(kReplicates, 2);
        for (int k = 0; k < kReplicates; ++k) {
            const auto d = draw();
            null(k, 0) = d[0], null(k, 1) = d[1];
        }
        const auto real = draw();
        const StepPValues p = step_p_values(null, real[0], real[1], margin);
        const double smaller = std::min(p.impulse, real[1] > margin ? p.rival : 1.0);
        ASSERT_GE(p.combined, smaller - 1e-12);
        ASSERT_LE(p.combined, 2.0 * smaller + 1e-12);
        rejected += p.combined <= 0.05;
    }
    const double rate = static_cast<double>(rejected) / kTrials;
    EXPECT_NEAR(rate, 4.0 / 80.0, 3.0 * std::sqrt(0.05 * 0.95 / kTrials));
}

// Where the rival never pays its price, the combined p is the impulse test's own.
TEST(LevelStep, WithoutTheRivalTheCombinedPIsTheImpulses) {
    Eigen::MatrixXd null(9, 2);
    for (int k = 0; k < 9; ++k) null(k, 0) = k, null(k, 1) = -1.0;
    const StepPValues p = step_p_values(null, 6.5, -1.0, 0.0);
    EXPECT_DOUBLE_EQ(p.impulse, 3.0 / 10.0);  // 6.5 itself, 7 and 8
    EXPECT_DOUBLE_EQ(p.combined, p.impulse);
}

// Instants 1..n s and `mean(k, t)` plus white noise of deviation `sigma`.
std::pair<std::vector<double>, std::vector<double>> noisy_series(
    std::size_t n, unsigned seed, double sigma, const std::function<double(std::size_t, double)>& mean) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    std::vector<double> t(n), x(n);
    for (std::size_t k = 0; k < n; ++k) {
        t[k] = static_cast<double>(k + 1);
        x[k] = noise(rng) + mean(k, t[k]);
    }
    return {t, x};
}

// The constant alone as the columns fitted beside the steps: change points in mean.
Eigen::MatrixXd level_column(std::size_t n) {
    return Eigen::MatrixXd::Constant(static_cast<Eigen::Index>(n), 1, 1.0 / std::sqrt(static_cast<double>(n)));
}

// A mean shape against two level steps (steps_over_shape()). The change points are the least-squares optimum: on a
// hop and a return in white noise they match a brute-force search over every pair of cuts, and lie where planted.
TEST(StepsOverShape, TheTwoStepsAreTheLeastSquaresOptimumAndLieWherePlanted) {
    const std::size_t n = 400;
    const auto [t, x] =
        noisy_series(n, 5, 0.4, [](std::size_t k, double) { return (k >= 150 ? 1.0 : 0.0) - (k >= 290 ? 0.7 : 0.0); });
    const StepsOverShape s = steps_over_shape(t, x, x, 2, 1.0, level_column(n));
    ASSERT_TRUE(s.tested);
    EXPECT_NEAR(s.steps[0].t_s, t[150], 3.0);
    EXPECT_NEAR(s.steps[1].t_s, t[290], 3.0);
    EXPECT_NEAR(s.steps[0].size_counts, 1.0, 0.15);
    EXPECT_NEAR(s.steps[1].size_counts, -0.7, 0.15);
    // Brute force over every pair of cuts (pieces of at least two outputs, 2 % clear of the ends).
    auto rss = [&](std::size_t a, std::size_t b) {
        double sum = 0, sum2 = 0;
        for (std::size_t k = a; k < b; ++k) sum += x[k], sum2 += x[k] * x[k];
        return sum2 - sum * sum / static_cast<double>(b - a);
    };
    double best = 1e300;
    for (std::size_t c1 = 8; c1 + 8 < n; ++c1)
        for (std::size_t c2 = c1 + 2; c2 + 8 < n; ++c2) best = std::min(best, rss(0, c1) + rss(c1, c2) + rss(c2, n));
    double total = 0.0;
    for (double v : x) total += v * v;
    // The statistic against a "shape" that explains nothing is the Gaussian likelihood ratio of the optimum.
    EXPECT_NEAR(s.statistic, 0.5 * static_cast<double>(n) * std::log(total / best), 1e-9);
    EXPECT_NEAR(s.margin, 0.5 * 2.0 * std::log(static_cast<double>(n)), 1e-12);
    EXPECT_TRUE(s.steps_win);
}

// The two steps of least residual beside the orthonormal columns `q`, by brute force over every pair of cuts whose
// least-squares sizes have opposite signs (a hop and its return): their cuts, sizes and residual sum of squares.
struct BruteSteps {
    std::size_t c1 = 0, c2 = 0;
    double size1 = 0.0, size2 = 0.0, rss = 1e300;
};

BruteSteps brute_hop_and_return(const std::vector<double>& x, const Eigen::MatrixXd& q, std::size_t edge) {
    const std::size_t n = x.size();
    const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(n));
    BruteSteps best;
    for (std::size_t c1 = edge; c1 + edge < n; ++c1)
        for (std::size_t c2 = c1 + 2; c2 + edge < n; ++c2) {
            Eigen::MatrixXd a(n, q.cols() + 2);
            a.leftCols(q.cols()) = q;
            for (std::size_t k = 0; k < n; ++k) {
                a(static_cast<Eigen::Index>(k), q.cols()) = k >= c1 ? 1.0 : 0.0;
                a(static_cast<Eigen::Index>(k), q.cols() + 1) = k >= c2 ? 1.0 : 0.0;
            }
            const Eigen::VectorXd b = a.colPivHouseholderQr().solve(y);
            const double v = (y - a * b).squaredNorm();
            if (b(q.cols()) * b(q.cols() + 1) < 0.0 && v < best.rss) best = {c1, c2, b(q.cols()), b(q.cols() + 1), v};
        }
    return best;
}

// Beside fitted columns (eq. 1's tangent, which the shape's own fit refits too), the two steps are the joint least-
// squares optimum of the columns and a hop and a return: a brute-force search over every pair of cuts, each fitted by
// QR, finds the same residual sum of squares and the same sizes, on a hop early in a drift that bends toward it.
TEST(StepsOverShape, BesideFittedColumnsTheStepsAreTheJointLeastSquaresOptimum) {
    const std::size_t n = 200;
    const auto [t, x] = noisy_series(n, 8, 0.3, [](std::size_t k, double t_s) {
        return 2.0 * std::exp(-t_s / 60.0) + (k >= 40 ? 1.0 : 0.0) - (k >= 150 ? 0.6 : 0.0);
    });
    const Eigen::MatrixXd q = orthonormal_basis(eq1_tangent(t, 60.0));
    const StepsOverShape s = steps_over_shape(t, x, x, 2, 1.0, q);
    ASSERT_TRUE(s.tested);
    const BruteSteps best = brute_hop_and_return(x, q, 4);  // 2 % of 200 outputs
    EXPECT_NEAR(best.c1, 40u, 3u);
    EXPECT_NEAR(best.c2, 150u, 3u);
    EXPECT_EQ(s.steps[0].t_s, t[best.c1]);
    EXPECT_EQ(s.steps[1].t_s, t[best.c2]);
    EXPECT_NEAR(s.steps[0].size_counts, best.size1, 1e-9);
    EXPECT_NEAR(s.steps[1].size_counts, best.size2, 1e-9);
    double total = 0.0;
    for (double v : x) total += v * v;
    EXPECT_NEAR(s.statistic, 0.5 * static_cast<double>(n) * std::log(total / best.rss), 1e-9);
}

// Two steps the same way (a staircase, as a warm-up's unmodelled curvature leaves) are no hop and return: the rival
// is the best pair of opposite signs (a brute-force search over every pair), which fits the staircase far worse than
// the staircase's own two steps would.
TEST(StepsOverShape, TheRivalIsAHopAndAReturnNotAStaircase) {
    const std::size_t n = 200;
    const auto [t, x] =
        noisy_series(n, 9, 0.3, [](std::size_t k, double) { return (k >= 50 ? 1.0 : 0.0) + (k >= 120 ? 1.0 : 0.0); });
    const Eigen::MatrixXd q = level_column(n);
    const StepsOverShape s = steps_over_shape(t, x, x, 2, 1.0, q);
    ASSERT_TRUE(s.tested);
    EXPECT_LT(s.steps[0].size_counts * s.steps[1].size_counts, 0.0);
    const BruteSteps best = brute_hop_and_return(x, q, 4);
    double total = 0.0;
    for (double v : x) total += v * v;
    // The alternating scans are exact for either cut given the other, not jointly: their pair may be another of
    // the near-ties a staircase offers (one step and a slight return), fitting within 1 % as well.
    const double found = total * std::exp(-2.0 * s.statistic / static_cast<double>(n));
    EXPECT_NEAR(found, best.rss, 0.01 * best.rss);
    // The staircase's own steps (piecewise means) leave the noise alone; the best hop and return leave much more.
    double staircase = 0.0;
    for (const auto& [from, to] : {std::pair<std::size_t, std::size_t>{0, 50}, {50, 120}, {120, n}}) {
        double sum = 0.0, sum2 = 0.0;
        for (std::size_t k = from; k < to; ++k) sum += x[k], sum2 += x[k] * x[k];
        staircase += sum2 - sum * sum / static_cast<double>(to - from);
    }
    EXPECT_GT(best.rss, 2.0 * staircase);
}

// A shape that describes the log (its residual is the noise alone) keeps it: the steps would have to fit the noise
// better by more than their price. Overlapping windows (a long-run factor of 3) count each output a third.
TEST(StepsOverShape, AShapeThatFitsIsKeptAndSharedNoiseCountsLess) {
    std::mt19937_64 rng(6);
    std::normal_distribution<double> noise(0.0, 0.4);
    const std::size_t n = 1500;
    std::vector<double> t(n), shaped(n), residual(n);
    for (std::size_t k = 0; k < n; ++k) {
        t[k] = static_cast<double>(k + 1);
        residual[k] = noise(rng);
        shaped[k] = residual[k] + 0.8 * std::sin(2.0 * M_PI * t[k] / 300.0);  // five cycles: no pair of steps
    }
    const StepsOverShape kept = steps_over_shape(t, shaped, residual, 3, 1.0, level_column(n));
    EXPECT_FALSE(kept.steps_win) << kept.statistic << " vs " << kept.margin;
    EXPECT_LT(kept.statistic, 0.0);
    const StepsOverShape shared = steps_over_shape(t, shaped, residual, 3, 3.0, level_column(n));
    EXPECT_NEAR(shared.statistic, kept.statistic / 3.0, 1e-9);
    EXPECT_NEAR(shared.margin, 0.5 * std::log(500.0), 1e-12);
}

}  // namespace
}  // namespace driftlab::host::gap
