// `driftlab gap LOG --truth LOG.truth.csv` on logs of a moving unit (docs/gap.md §A log in motion): a scale factor
// planted on a turntable is named and sized, a clean figure8 leaves nothing to explain, and a truth that is not the
// log's is refused naming its line.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "e2e_support.hpp"

namespace driftlab::e2e {
namespace {

RunResult hil(const TempDir& dir, const std::string& trajectory, const std::string& seconds, const std::string& log,
              const std::string& model = "") {
    std::vector<std::string> args = {"hil", "--trajectory", trajectory, "--duration", seconds,      "--period",
                                     "0.1", "--seed",       "4",        "-o",         dir.file(log)};
    if (!model.empty()) {
        std::ofstream(dir.file("m.toml")) << model;
        args.insert(args.end(), {"--model", dir.file("m.toml")});
    }
    return run_driftlab(args, dir.path());
}

nlohmann::json gap_json(const TempDir& dir, const std::string& log, const std::string& truth) {
    const RunResult r = run_driftlab({"gap", dir.file(log), "--truth", dir.file(truth), "--json"}, dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return nlohmann::json::parse(r.output.substr(r.output.find('{')));
}

// The check: a 2 % gyro scale-factor error on the turntable is named and recovered within 10 %.
TEST(GapTruthCli, AScaleFactorPlantedOnATurntableIsNamedAndSized) {
    TempDir dir("gaptruth_sf");
    ASSERT_EQ(
        hil(dir, "turntable", "1200", "t.csv", "[effects.scale_factor]\nerror_pct = [2.0, 0.0, 0.0, 0.0]\n").exit_code,
        0);
    const nlohmann::json j = gap_json(dir, "t.csv", "t.truth.csv");
    EXPECT_EQ(j["verdict"], "scale_factor");
    bool seen = false;
    for (const auto& t : j["motion"]["terms"]) {
        if (t["parameter"] != "error_pct[0]") {
            EXPECT_FALSE(t.value("accepted", false)) << t.dump();
            continue;
        }
        seen = true;
        EXPECT_TRUE(t["accepted"].get<bool>());
        EXPECT_NEAR(t["value"].get<double>(), 2.0, 0.2) << t.dump();
    }
    EXPECT_TRUE(seen);
    // The turntable turns in place: nothing excites the accelerometers' terms or the g-sensitivity.
    for (const auto& t : j["motion"]["terms"]) {
        if (t["channel"] != "gyro" || t["effect"] == "g_sensitivity") {
            EXPECT_FALSE(t["tested"].get<bool>()) << t.dump();
        }
    }
}

// A clean unit on figure8: the known input taken out leaves a unit at rest, and no motion term is accepted.
TEST(GapTruthCli, ACleanFigure8LeavesNothingToExplain) {
    TempDir dir("gaptruth_f8");
    ASSERT_EQ(hil(dir, "figure8", "600", "f.csv").exit_code, 0);
    const nlohmann::json j = gap_json(dir, "f.csv", "f.truth.csv");
    EXPECT_EQ(j["verdict"], "none");
    EXPECT_TRUE(j["located"].empty());
    int tested = 0;
    for (const auto& t : j["motion"]["terms"]) {
        EXPECT_FALSE(t.value("accepted", false)) << t.dump();
        tested += t["tested"].get<bool>() ? 1 : 0;
    }
    EXPECT_GE(tested, 5) << "figure8 excites the scale factors and the cross-axis terms";
    EXPECT_EQ(j["motion"]["input_source"].get<std::string>().rfind("trajectory figure8 rebuilt", 0), 0u);
}

// A truth that is not the log's: refused naming the truth's line; a plain table takes no truth.
TEST(GapTruthCli, ATruthThatIsNotTheLogsIsRefusedNamingItsLine) {
    TempDir dir("gaptruth_bad");
    ASSERT_EQ(hil(dir, "figure8", "60", "a.csv").exit_code, 0);
    ASSERT_EQ(hil(dir, "figure8", "90", "b.csv").exit_code, 0);
    const RunResult longer = run_driftlab({"gap", dir.file("a.csv"), "--truth", dir.file("b.truth.csv")}, dir.path());
    EXPECT_EQ(longer.exit_code, 3) << longer.output;
    EXPECT_NE(longer.output.find(dir.file("b.truth.csv") + ":"), std::string::npos) << longer.output;
    EXPECT_NE(longer.output.find("is this the truth of that log?"), std::string::npos) << longer.output;
    const RunResult shorter = run_driftlab({"gap", dir.file("b.csv"), "--truth", dir.file("a.truth.csv")}, dir.path());
    EXPECT_EQ(shorter.exit_code, 3) << shorter.output;
    std::ofstream(dir.file("p.txt")) << "1\n2\n3\n";
    const RunResult plain = run_driftlab(
        {"gap", dir.file("p.txt"), "--tau0", "1", "--as", "gyro=col1:1", "--truth", dir.file("a.truth.csv")},
        dir.path());
    EXPECT_EQ(plain.exit_code, 2) << plain.output;
    EXPECT_NE(plain.output.find("--truth takes the ground truth of a canonical log"), std::string::npos)
        << plain.output;
}

}  // namespace
}  // namespace driftlab::e2e
