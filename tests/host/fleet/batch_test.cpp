// The batch of a fleet: the standout limit holds its false rate on batches without outliers (a property, checked by
// fresh simulation), a planted board is named for its parameter and no other, a value the log determines poorly is
// not named for its noise, and the medians and spreads are those of the values.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "host/fleet/batch.hpp"
#include "host/fleet/standout_limit.hpp"
#include "host/stats/median.hpp"

namespace driftlab::host::fleet {
namespace {

// Boards with gyro C2 (linear) and T (log scale) from `c2` and `t`, each with standard error `se` of its own unit.
std::vector<BoardEntry> boards_of(const std::vector<double>& c2, const std::vector<double>& t, double se = 0.0) {
    std::vector<BoardEntry> out;
    for (std::size_t i = 0; i < c2.size(); ++i) {
        ChannelResult ch;
        ch.channel = "gyro";
        ch.parameters[1] = {c2[i], se, true};
        ch.parameters[2] = {t[i], se * t[i], true};
        BoardResult r;
        r.channels.push_back(ch);
        out.push_back({"b" + std::to_string(i), r, ""});
    }
    return out;
}

TEST(StandoutLimit, BatchesWithoutOutliersNameABoardInFivePerCentOfFleets) {
    constexpr std::size_t kBoards = 20, kParameters = 8, kFleets = 2000;
    const double limit = standout_limit(kBoards, kParameters);
    std::mt19937_64 rng(99);  // not the limit's own draws
    std::normal_distribution<double> z;
    std::size_t named = 0;
    for (std::size_t f = 0; f < kFleets; ++f) {
        bool any = false;
        for (std::size_t p = 0; p < kParameters; ++p) {
            std::vector<double> x(kBoards), d(kBoards);
            for (double& v : x) v = z(rng);
            const double m = stats::median(x);
            for (std::size_t i = 0; i < kBoards; ++i) d[i] = std::fabs(x[i] - m);
            const double scale = kMadToSigma * stats::median(d);
            for (const double v : d) any = any || v / scale > limit;
        }
        named += any ? 1 : 0;
    }
    // 5 % of 2000 is 100, binomial standard deviation 9.7.
    EXPECT_GT(named, 65u);
    EXPECT_LT(named, 135u);
    // More parameters judged, a higher limit; more boards, a tighter scale and a lower one.
    EXPECT_GT(standout_limit(kBoards, 30), limit);
    EXPECT_LT(standout_limit(200, kParameters), limit);
}

TEST(FleetBatch, APlantedBoardIsNamedForItsParameterAlone) {
    std::mt19937_64 rng(5);
    std::normal_distribution<double> z;
    std::vector<double> c2, t;
    for (int i = 0; i < 20; ++i) c2.push_back(505 + z(rng)), t.push_back(411 * std::exp(0.1 * z(rng)));
    t[7] *= 3.0;  // ln 3 = 11 spreads of 0.1
    const Batch b = summarise(boards_of(c2, t));
    ASSERT_EQ(b.standouts.size(), 1u);
    EXPECT_EQ(b.standouts[0].board, 7u);
    EXPECT_EQ(b.standouts[0].parameter, "T");
    EXPECT_GT(b.standouts[0].z, 8.0);
    ASSERT_EQ(b.distributions.size(), 2u);
    EXPECT_EQ(b.distributions[0].median, stats::median(c2));
    std::vector<double> deviation;
    for (const double v : c2) deviation.push_back(std::fabs(v - stats::median(c2)));
    EXPECT_DOUBLE_EQ(b.distributions[0].spread, 1.4826 * stats::median(deviation));
    EXPECT_GT(b.distributions[1].factor, 1.0);
    EXPECT_EQ(b.distributions[1].low, *std::min_element(t.begin(), t.end()));
}

TEST(FleetBatch, AValueItsLogDeterminesPoorlyIsNotNamedForItsNoise) {
    std::vector<double> c2(20, 0.0), t(20, 411.0);
    for (int i = 0; i < 20; ++i) c2[i] = 505 + 0.1 * (i % 5);
    c2[3] = 510;  // 50 spreads off, but each value is known to +-5 counts only
    EXPECT_EQ(summarise(boards_of(c2, t)).standouts.size(), 1u);
    EXPECT_TRUE(summarise(boards_of(c2, t, 5.0)).standouts.empty());
}

TEST(FleetBatch, AFailedChannelStandsOutAndALogThatCouldNotBeReadIsNotABoard) {
    std::vector<BoardEntry> boards = boards_of(std::vector<double>(6, 505.0), std::vector<double>(6, 411.0));
    boards[2].result->channels[0].error = "constant";
    boards.push_back({"notes.csv", std::nullopt, "not a driftlab log"});
    const Batch b = summarise(boards);
    EXPECT_EQ(b.boards, 7u);
    EXPECT_EQ(b.analysed, 6u);
    ASSERT_EQ(b.standouts.size(), 1u);
    EXPECT_EQ(b.standouts[0].board, 2u);
    EXPECT_EQ(b.standouts[0].parameter, "analysis");
}

}  // namespace
}  // namespace driftlab::host::fleet
