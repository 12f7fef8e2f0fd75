// `driftlab gap-eval` as a user runs it: its option checks come before minutes of benchmark, and --raw-clean and
// --clean-only change what the clean logs are.
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "e2e_support.hpp"
#include "host/gap_eval/truth.hpp"

namespace driftlab::e2e {
namespace {

// A plot folder that cannot be made is refused before minutes of benchmark, not after them.
TEST(GapEvalCli, AnUnusablePlotFolderIsRefusedBeforeTheRun) {
    TempDir dir("gapevalplot");
    const std::string blocker = dir.file("file");
    std::ofstream(blocker) << "not a folder\n";
    const RunResult r =
        run_driftlab({"gap-eval", "--quick", "--effects", "thermal_rc", "--plot", blocker + "/plots"}, dir.path());
    EXPECT_EQ(r.exit_code, 4) << r.output;
    EXPECT_NE(r.output.find("cannot create the plot folder"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("| generator"), std::string::npos) << "no benchmark output before the refusal";
}

// --raw-clean makes the clean logs raw-mode: the scores say so, and the false-positive line names them.
TEST(GapEvalCli, RawCleanLogsAreReportedAsRawMode) {
    TempDir dir("gapevalraw");
    const std::vector<std::string> base{"gap-eval", "--clean-only",     "--quick", "--seeds-score",
                                        "11..12",   "--clean-per-seed", "2"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = base;
        args.insert(args.end(), extra.begin(), extra.end());
        return run_driftlab(args, dir.path());
    };
    const RunResult raw = with({"--raw-clean", "--json"});
    ASSERT_EQ(raw.exit_code, 0) << raw.output;
    const auto j = nlohmann::json::parse(raw.output.substr(raw.output.find('{')));
    EXPECT_EQ(j["false_positive"]["clean"], 4);
    EXPECT_TRUE(j["false_positive"]["raw_mode"].get<bool>());
    const RunResult plain = with({"--json"});
    ASSERT_EQ(plain.exit_code, 0) << plain.output;
    EXPECT_FALSE(
        nlohmann::json::parse(plain.output.substr(plain.output.find('{')))["false_positive"]["raw_mode"].get<bool>());
    const RunResult md = with({"--raw-clean"});
    EXPECT_NE(md.output.find("False-positive rate on clean raw-mode logs: "), std::string::npos) << md.output;
    // The other clean forms: outputs that are codes, and a lossy link; one form at a time.
    const RunResult codes = with({"--codes-clean", "--json", "--samples", "600"});
    ASSERT_EQ(codes.exit_code, 0) << codes.output;
    const auto c = nlohmann::json::parse(codes.output.substr(codes.output.find('{')));
    EXPECT_TRUE(c["false_positive"]["codes"].get<bool>());
    EXPECT_FALSE(c["false_positive"]["raw_mode"].get<bool>());
    const RunResult link = with({"--link-clean"});
    EXPECT_NE(link.output.find("False-positive rate on clean lossy-link logs: "), std::string::npos) << link.output;
    const RunResult both = with({"--raw-clean", "--link-clean"});
    EXPECT_EQ(both.exit_code, 2) << both.output;
    const RunResult short_logs = with({"--samples", "100"});
    EXPECT_EQ(short_logs.exit_code, 2) << short_logs.output;
    EXPECT_NE(short_logs.output.find("--samples"), std::string::npos) << short_logs.output;
}

// --clean-only without --clean-per-seed takes as many clean logs per seed as the run has sizes (--quick: one), not
// none.
TEST(GapEvalCli, CleanOnlyWithoutACountStillDiagnosesCleanLogs) {
    TempDir dir("gapevalclean");
    const RunResult r =
        run_driftlab({"gap-eval", "--clean-only", "--quick", "--seeds-score", "11..13", "--json"}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // 3 seeds x 1 size
    EXPECT_EQ(nlohmann::json::parse(r.output.substr(r.output.find('{')))["false_positive"]["clean"], 3);
    // It tunes nothing, so scoring seeds among the default tuning ones (1..4) are no overlap.
    const RunResult low =
        run_driftlab({"gap-eval", "--clean-only", "--quick", "--seeds-score", "1..2", "--json"}, dir.path());
    ASSERT_EQ(low.exit_code, 0) << low.output;
    EXPECT_EQ(nlohmann::json::parse(low.output.substr(low.output.find('{')))["false_positive"]["clean"], 2);
}

// A seed range is two whole numbers in order, at most kMaxEvalSeed: "-1" is no number (not 2^64 - 1, which ran
// forever).
TEST(GapEvalCli, ASeedRangeOfNegativeOrHugeNumbersIsRefused) {
    TempDir dir("gapevalrange");
    for (const std::string range : {"101..-1", "-3..4", "1..2000000", "5..4", "1..2x", "..4"}) {
        const RunResult r = run_driftlab({"gap-eval", "--quick", "--seeds-score", range}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << range << ": " << r.output;
        EXPECT_NE(r.output.find("--seeds-score: expected A..B with whole numbers 0 <= A <= B <= 1000000, got '" +
                                range + "'"),
                  std::string::npos)
            << r.output;
    }
}

// --pairs names two generators of library effects that act at the converter input; anything else is a usage error
// naming the pair, before any log is made.
TEST(GapEvalCli, ABadPairIsRefusedNamingIt) {
    TempDir dir("gapevalpairs");
    auto refused = [&](const std::string& pair, const std::string& message) {
        const RunResult r =
            run_driftlab({"gap-eval", "--quick", "--effects", "thermostat", "--pairs", pair}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << pair << ": " << r.output;
        EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("| generator"), std::string::npos) << "no benchmark output before the refusal";
    };
    refused("thermostat", "--pairs: expected A+B, got 'thermostat'");
    refused("thermostat+ambient_cycle", "names one generator twice");
    refused("thermostat+mode_hop", "--pairs: mode_hop stands for no library effect");
    refused("sar_mismatch+flicker", "--pairs: sar_mismatch replaces the converter");
    refused("thermostat+wobble", "--pairs: unknown generator or effect 'wobble'");
    refused("none+thermostat", "--pairs: unknown generator or effect 'none'");
    // A misspelt name is answered with the names there are.
    const RunResult misspelt = run_driftlab({"gap-eval", "--quick", "--effects", "thermostatt"}, dir.path());
    EXPECT_EQ(misspelt.exit_code, 2) << misspelt.output;
    for (const auto& t : host::gap::truth_list())
        EXPECT_NE(misspelt.output.find(t.generator), std::string::npos) << t.generator;
}

}  // namespace
}  // namespace driftlab::e2e
