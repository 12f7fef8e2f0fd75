// Campaigns in shards, as a Slurm array runs them: `gap-eval --quick` in 1, 3 and 7 shards, merged, prints
// byte for byte what the one-process run prints (--json); a shard run twice writes the same bytes; a missing,
// repeated or foreign part, or a file that is no part, is refused with its name.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "e2e_support.hpp"

namespace driftlab::e2e {
namespace {

std::string file_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The parts of `gap-eval --quick` in `n` shards, in `dir` (named NAME<n>_<k>.part).
std::vector<std::string> shards(const TempDir& dir, int n, const std::vector<std::string>& extra = {},
                                const std::string& name = "q") {
    std::vector<std::string> parts;
    for (int k = 0; k < n; ++k) {
        parts.push_back(dir.file(name + std::to_string(n) + "_" + std::to_string(k) + ".part"));
        std::vector<std::string> args = {
            "gap-eval", "--quick", "--shard", std::to_string(k) + "/" + std::to_string(n), "-o", parts.back()};
        args.insert(args.end(), extra.begin(), extra.end());
        const RunResult r = run_driftlab(args, dir.path());
        EXPECT_EQ(r.exit_code, 0) << r.output;
    }
    return parts;
}

SplitRun merged(const TempDir& dir, const std::vector<std::string>& parts) {
    std::vector<std::string> args = {"merge", "--json"};
    args.insert(args.end(), parts.begin(), parts.end());
    return run_driftlab_split(args, dir.path());
}

TEST(MergeCli, AQuickCampaignInOneThreeOrSevenShardsMergesToTheOneProcessRun) {
    TempDir dir("merge");
    const SplitRun one = run_driftlab_split({"gap-eval", "--quick", "--json"}, dir.path());
    ASSERT_EQ(one.exit_code, 0) << one.err;
    for (int n : {1, 3, 7}) {
        const std::vector<std::string> parts = shards(dir, n);
        const SplitRun m = merged(dir, parts);
        ASSERT_EQ(m.exit_code, 0) << m.err;
        EXPECT_EQ(m.out, one.out) << n << " shards";
    }
    // In two stages: a_50 measured in 3 shards and merged once, then the cases in 2 shards reading it.
    const std::vector<std::string> sized = shards(dir, 3, {"--measure-sizes"}, "sizes");
    std::vector<std::string> join = {"merge", "-o", dir.file("sizes")};
    join.insert(join.end(), sized.begin(), sized.end());
    const RunResult joined = run_driftlab(join, dir.path());
    ASSERT_EQ(joined.exit_code, 0) << joined.output;
    const SplitRun staged = merged(dir, shards(dir, 2, {"--sizes", dir.file("sizes")}, "staged"));
    ASSERT_EQ(staged.exit_code, 0) << staged.err;
    EXPECT_EQ(staged.out, one.out) << "two stages";
    // A sizes shard is not the sizes; nor are another campaign's.
    const RunResult unmerged = run_driftlab({"gap-eval", "--quick", "--sizes", sized.front()}, dir.path());
    EXPECT_EQ(unmerged.exit_code, 3);
    EXPECT_NE(unmerged.output.find("give their merge"), std::string::npos) << unmerged.output;
    const RunResult foreign_sizes =
        run_driftlab({"gap-eval", "--quick", "--samples", "900", "--sizes", dir.file("sizes")}, dir.path());
    EXPECT_EQ(foreign_sizes.exit_code, 3);
    EXPECT_NE(foreign_sizes.output.find(dir.file("sizes") + ": the sizes of another campaign"), std::string::npos)
        << foreign_sizes.output;
    // A shard run again writes the same bytes.
    const std::string first = file_bytes(dir.file("q3_1.part"));
    const RunResult again =
        run_driftlab({"gap-eval", "--quick", "--shard", "1/3", "-o", dir.file("q3_1.part")}, dir.path());
    ASSERT_EQ(again.exit_code, 0) << again.output;
    EXPECT_EQ(file_bytes(dir.file("q3_1.part")), first);
    // Missing, repeated, foreign, not a part: refused, naming the file.
    const auto refused = [&](const std::vector<std::string>& parts, const std::string& said) {
        const SplitRun m = merged(dir, parts);
        EXPECT_EQ(m.exit_code, 3) << m.err;
        EXPECT_NE(m.err.find(said), std::string::npos) << m.err;
        EXPECT_TRUE(m.out.empty());
    };
    refused({dir.file("q3_0.part"), dir.file("q3_1.part")}, "shard 2/3 of its campaign is missing");
    refused({dir.file("q3_0.part"), dir.file("q3_1.part"), dir.file("q3_1.part"), dir.file("q3_2.part")},
            dir.file("q3_1.part") + ": shard 1/3 again");
    refused({dir.file("q3_0.part"), dir.file("q7_1.part"), dir.file("q3_2.part")},
            dir.file("q7_1.part") + ": one of 7 shards, not 3");
    const std::vector<std::string> other = shards(dir, 1, {"--effects", "thermal_rc", "--seeds-score", "201..202"});
    refused({dir.file("q3_0.part"), dir.file("q3_1.part"), other.front()}, other.front() + ": of another campaign");
    std::ofstream(dir.file("notes.part")) << "not a part\n";
    refused({dir.file("notes.part")}, dir.file("notes.part") + ": not a gap-eval part");
}

// A nav-eval campaign's seeds in 1 and 3 shards (each seed's rest recording and its trajectories in one shard),
// merged: the one-process run's JSON and text, byte for byte; a gap-eval part among nav-eval ones is refused.
TEST(MergeCli, ANavEvalCampaignInShardsMergesToTheOneProcessRun) {
    TempDir dir("navmerge");
    const std::vector<std::string> campaign = {"--runs",         "4",    "--duration",     "320",
                                               "--fit-duration", "1200", "--trajectories", "stop-and-go,square"};
    const auto one = [&](bool json) {
        std::vector<std::string> args = {"nav-eval"};
        args.insert(args.end(), campaign.begin(), campaign.end());
        if (json) args.push_back("--json");
        return run_driftlab_split(args, dir.path());
    };
    const SplitRun json = one(true), text = one(false);
    ASSERT_EQ(json.exit_code, 0) << json.err;
    for (int n : {1, 3}) {
        std::vector<std::string> parts;
        for (int k = 0; k < n; ++k) {
            parts.push_back(dir.file("n" + std::to_string(n) + "_" + std::to_string(k)));
            std::vector<std::string> args = {"nav-eval", "--shard", std::to_string(k) + "/" + std::to_string(n), "-o",
                                             parts.back()};
            args.insert(args.end(), campaign.begin(), campaign.end());
            const RunResult r = run_driftlab(args, dir.path());
            ASSERT_EQ(r.exit_code, 0) << r.output;
        }
        EXPECT_EQ(merged(dir, parts).out, json.out) << n << " shards";
        std::vector<std::string> args = {"merge"};
        args.insert(args.end(), parts.rbegin(), parts.rend());
        EXPECT_EQ(run_driftlab_split(args, dir.path()).out, text.out) << n << " shards";
    }
    const std::vector<std::string> gap = shards(dir, 1, {"--effects", "thermal_rc", "--seeds-score", "201..202"});
    const SplitRun mixed = merged(dir, {dir.file("n3_0"), gap.front()});
    EXPECT_EQ(mixed.exit_code, 3);
    EXPECT_NE(mixed.err.find(gap.front() + ": not a nav-eval part"), std::string::npos) << mixed.err;
}

TEST(MergeCli, AShardNeedsItsPartFileAndABadShardIsRefused) {
    TempDir dir("shardargs");
    for (const std::string bad : {"3/3", "1/0", "a/2", "2", "-1/4"}) {
        const RunResult r = run_driftlab({"gap-eval", "--quick", "--shard", bad, "-o", dir.file("p")}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.output;
        EXPECT_NE(r.output.find("--shard"), std::string::npos) << r.output;
    }
    const RunResult alone = run_driftlab({"gap-eval", "--quick", "--shard", "0/2"}, dir.path());
    EXPECT_EQ(alone.exit_code, 2) << alone.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("p")));
}

}  // namespace
}  // namespace driftlab::e2e
