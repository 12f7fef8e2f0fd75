// The level-step test: a hop and a return planted on top of a random walk are found where and about as large as they
// were planted, while the same random walk without them passes.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "gap_fixtures.hpp"
#include "host/gap/candidates.hpp"
#include "host/gap/level_step.hpp"

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

TEST(LevelStep, AHopAndReturnOnARandomWalkAreFoundWhereAndAsLargeAsTheyWere) {
    std::vector<double> hop(2000, 0.0);
    for (std::size_t k = 700; k < 1400; ++k) hop[k] = 1.5;  // counts: up at t = 700.5 s, back at 1400.5 s
    for (std::uint64_t seed : {31, 32, 33, 34, 35}) {
        const LevelStep s = run(walk_model(), hop, seed);
        EXPECT_TRUE(s.significant) << "seed " << seed << " p " << s.p_value << " statistic " << s.statistic;
        EXPECT_GT(s.statistic, s.margin) << "seed " << seed;
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

// The Monte Carlo part is a level-alpha test: of eight logs from the model itself at most two may be flagged
// (binomial, 5 %: probability 0.6 %; the likelihood margin only lowers the rate).
TEST(LevelStep, TheModelsOwnLogsPass) {
    int flagged = 0;
    for (std::uint64_t seed = 41; seed < 49; ++seed) flagged += run(walk_model(), {}, seed).significant;
    EXPECT_LE(flagged, 2);
}

}  // namespace
}  // namespace driftlab::host::gap
