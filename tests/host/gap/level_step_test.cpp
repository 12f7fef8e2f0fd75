// The level-step test: a step planted on top of a random walk is found where and about as large as it was planted,
// while the same random walk without it, or a clean log, passes.
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

TEST(LevelStep, AStepOnARandomWalkIsFoundWhereAndAsLargeAsItWas) {
    std::vector<double> step(2000, 0.0);
    for (std::size_t k = 1200; k < step.size(); ++k) step[k] = 1.5;  // counts, at t = 1200.5 s
    for (std::uint64_t seed : {31, 32, 33}) {
        const LevelStep s = run(walk_model(), step, seed);
        EXPECT_TRUE(s.significant) << "seed " << seed << " p " << s.p_value;
        EXPECT_NEAR(s.t_s, 1200.5, 20.0) << "seed " << seed;
        EXPECT_NEAR(s.size_counts, 1.5, 0.5) << "seed " << seed;
    }
}

// The test is a level-alpha Monte Carlo test: of eight logs from the model itself at most two may be flagged
// (binomial, 5 %: probability 0.6 %).
TEST(LevelStep, TheModelsOwnLogsPass) {
    int flagged = 0;
    for (std::uint64_t seed = 41; seed < 49; ++seed) flagged += run(walk_model(), {}, seed).significant;
    EXPECT_LE(flagged, 2);
}

}  // namespace
}  // namespace driftlab::host::gap
