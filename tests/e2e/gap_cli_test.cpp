// `driftlab gap` as a user runs it on a log of the full host-in-the-loop chain (native firmware, frames, radio
// link): the diagnosis's in-process replicate chain leaves out frames and link, so a log the simulator made must
// come out with no gap. And bad input is refused with a message naming the file.
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "e2e_support.hpp"

namespace driftlab::e2e {
namespace {

TEST(GapCli, TheSimulatorsOwnHilLogHasNoGap) {
    TempDir dir("gaphil");
    const std::string log = dir.file("hil.csv");
    const RunResult hil = run_driftlab({"hil", "--duration", "1500", "--seed", "3", "-o", log}, dir.path());
    ASSERT_EQ(hil.exit_code, 0) << hil.output;
    const RunResult gap = run_driftlab({"gap", log, "--replicates", "16", "--json"}, dir.path());
    ASSERT_EQ(gap.exit_code, 0) << gap.output;
    const auto j = nlohmann::json::parse(gap.output);
    EXPECT_EQ(j["verdict"], "none");
    EXPECT_TRUE(j["located"].empty());
    EXPECT_EQ(j["holdout"], "interleaved");
    // All four channels vary (drift and noise) and are analysed; the score is near 1 when nothing is missing.
    EXPECT_LT(j["gap_before"]["fit"].get<double>(), 2.0);
    EXPECT_LT(j["gap_before"]["heldout"].get<double>(), 2.0);
}

TEST(GapCli, ATooShortLogIsRefusedNamingTheFile) {
    TempDir dir("gapshort");
    const std::string log = dir.file("short.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "60", "-o", log}, dir.path()).exit_code, 0);
    const RunResult gap = run_driftlab({"gap", log}, dir.path());
    EXPECT_NE(gap.exit_code, 0);
    EXPECT_NE(gap.output.find("short.csv"), std::string::npos) << gap.output;
    EXPECT_NE(gap.output.find("at least 200 samples"), std::string::npos) << gap.output;
    const RunResult holdout = run_driftlab({"gap", log, "--holdout", "random"}, dir.path());
    EXPECT_NE(holdout.exit_code, 0);
    EXPECT_NE(holdout.output.find("--holdout"), std::string::npos) << holdout.output;
}

}  // namespace
}  // namespace driftlab::e2e
