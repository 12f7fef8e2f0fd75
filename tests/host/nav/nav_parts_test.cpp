// merge_nav_parts() against hand-made parts of a three-seed campaign in two shards: the runs come back seed by seed,
// each seed's trajectories in the campaign's order; a part holding a trajectory twice in a seed (its count still
// right), a seed twice, another shard's seed or one before the first, or missing a seed, is refused naming the file.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "host/nav/nav_parts.hpp"
#include "tests/support/data_error.hpp"
#include "tests/support/temp_dir.hpp"

namespace driftlab::host::nav {
namespace {

constexpr std::uint64_t kFirst = 100;

// Shard k of 2 holding `runs` (seed, trajectory).
NavPart part(std::size_t k, const std::vector<std::pair<std::uint64_t, std::string>>& runs) {
    NavPart p;
    p.campaign = {{"seed", kFirst}, {"trajectories", {"square", "stop-and-go"}}};
    p.build = "test";
    p.shard = k;
    p.shards = 2;
    p.seeds = 3;
    for (const auto& [seed, trajectory] : runs) p.runs.push_back({trajectory, seed, {}});
    return p;
}

std::vector<std::pair<std::uint64_t, std::string>> runs_of(const NavPart& p) {
    std::vector<std::pair<std::uint64_t, std::string>> out;
    for (const EvalRun& r : p.runs) out.emplace_back(r.seed, r.trajectory);
    return out;
}

TEST(NavParts, TwoShardsMergeSeedBySeedAndABadPartIsNamed) {
    test_support::TempDir dir("nav_parts");
    const std::string zero = dir.file("0.part"), one = dir.file("1.part"), bad = dir.file("bad.part");
    write_nav_part(part(0, {{100, "square"}, {100, "stop-and-go"}, {102, "square"}, {102, "stop-and-go"}}), zero);
    write_nav_part(part(1, {{101, "square"}, {101, "stop-and-go"}}), one);
    const std::vector<std::pair<std::uint64_t, std::string>> all = {{100, "square"}, {100, "stop-and-go"},
                                                                    {101, "square"}, {101, "stop-and-go"},
                                                                    {102, "square"}, {102, "stop-and-go"}};
    EXPECT_EQ(runs_of(merge_nav_parts({one, zero})), all);

    const auto refused = [&](const std::vector<std::pair<std::uint64_t, std::string>>& runs) {
        write_nav_part(part(0, runs), bad);
        return test_support::data_error_of([&] { merge_nav_parts({bad, one}); });
    };
    EXPECT_EQ(refused({{100, "square"}, {100, "square"}, {102, "square"}, {102, "stop-and-go"}}),
              bad + ": holds runs of seed 100 that are not the campaign's trajectories, each once in order");
    EXPECT_EQ(refused({{100, "square"},
                       {100, "stop-and-go"},
                       {102, "square"},
                       {102, "stop-and-go"},
                       {100, "square"},
                       {100, "stop-and-go"}}),
              bad + ": holds seed 100 twice");
    EXPECT_EQ(refused({{100, "square"}, {100, "stop-and-go"}, {101, "square"}, {101, "stop-and-go"}}),
              bad + ": holds seed 101, not shard 0's");
    EXPECT_EQ(refused({{98, "square"}, {98, "stop-and-go"}, {100, "square"}, {100, "stop-and-go"}}),
              bad + ": holds seed 98, not shard 0's");
    EXPECT_EQ(refused({{100, "square"}, {100, "stop-and-go"}}), bad + ": its parts miss seed 102");
}

}  // namespace
}  // namespace driftlab::host::nav
