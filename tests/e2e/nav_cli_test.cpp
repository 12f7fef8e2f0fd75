// `driftlab nav` and `driftlab nav-eval` from the command line (docs/nav.md): the forward correction's heading error
// at 10 min is a small fraction of raw's on the paper's unit from power-on, the estimate CSV has the documented
// columns and agrees with the JSON, nav and nav-eval share their JSON keys, and bad input is refused with its reason.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "e2e_support.hpp"

namespace driftlab::e2e {
namespace {

nlohmann::json parse_json(const RunResult& r) {
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return nlohmann::json::parse(r.output.substr(r.output.find('{')));
}

void make_logs(const TempDir& dir) {
    ASSERT_EQ(run_driftlab({"hil", "--duration", "1200", "--period", "0.1", "--seed", "2", "-o", dir.file("rest.csv")},
                           dir.path())
                  .exit_code,
              0);
    ASSERT_EQ(run_driftlab({"hil", "--trajectory", "stop-and-go", "--rest-before", "10", "--duration", "610",
                            "--period", "0.1", "--seed", "3", "-o", dir.file("sg.csv")},
                           dir.path())
                  .exit_code,
              0);
}

TEST(NavCli, ForwardCorrectionBeatsRawAndTheEstimateFileMatchesTheJson) {
    TempDir dir("nav_cli");
    make_logs(dir);
    const nlohmann::json j =
        parse_json(run_driftlab({"nav", dir.file("sg.csv"), "--truth", dir.file("sg.truth.csv"), "--fit-from",
                                 dir.file("rest.csv"), "--aid", "zupt", "--json", "-o", dir.file("est.csv")},
                                dir.path()));
    ASSERT_EQ(j["at_s"], nlohmann::json({60.0, 300.0, 600.0, 1800.0}));
    const auto& v = j["variants"];
    for (const char* name : {"raw", "forward", "ekf", "forward+ekf"}) ASSERT_TRUE(v.contains(name)) << name;
    // Table 1's gyro rises 3 counts (0.53 deg/s) with T = 411 s: raw's constant bias leaves most of it.
    const double raw10 = v["raw"]["heading_error_deg"][2].get<double>();
    const double fwd10 = v["forward"]["heading_error_deg"][2].get<double>();
    EXPECT_GT(raw10, 50.0);
    EXPECT_LT(fwd10 * 10.0, raw10);
    EXPECT_TRUE(v["raw"]["heading_error_deg"][3].is_null());  // the log ends before 30 min
    EXPECT_GT(v["forward+ekf"]["zero_velocity_updates"].get<int>(), 0);
    EXPECT_EQ(v["forward"]["zero_velocity_updates"].get<int>(), 0);  // dead reckoning takes no aid

    std::ifstream csv(dir.file("est.csv"));
    std::string header, line, last;
    std::getline(csv, header);
    EXPECT_EQ(header,
              "t_s,raw.x_m,raw.y_m,raw.heading_deg,forward.x_m,forward.y_m,forward.heading_deg,ekf.x_m,ekf.y_m,"
              "ekf.heading_deg,forward+ekf.x_m,forward+ekf.y_m,forward+ekf.heading_deg");
    std::size_t rows = 0;
    while (std::getline(csv, line)) last = line, ++rows;
    EXPECT_EQ(rows, j["rows"].get<std::size_t>());
    std::stringstream ss(last);
    std::string field;
    for (int k = 0; k <= 6; ++k) std::getline(ss, field, ',');
    EXPECT_DOUBLE_EQ(std::stod(field), v["forward"]["final"]["heading_deg"].get<double>());
}

TEST(NavCli, NavEvalSharesNavsKeys) {
    TempDir dir("nav_eval_cli");
    const nlohmann::json j = parse_json(
        run_driftlab({"nav-eval", "--runs", "2", "--duration", "320", "--fit-duration", "1200", "--json"}, dir.path()));
    EXPECT_EQ(j["runs"], 2);
    ASSERT_EQ(j["at_s"], nlohmann::json({60.0, 300.0, 600.0, 1800.0}));
    for (const char* name : {"raw", "forward", "ekf", "forward+ekf"}) {
        const auto& v = j["variants"][name];
        ASSERT_EQ(v["heading_error_deg"].size(), 4u) << name;
        ASSERT_EQ(v["heading_error_deg_p95"].size(), 4u) << name;
        ASSERT_EQ(v["position_error_m"].size(), 4u) << name;
        EXPECT_TRUE(v.contains("nees_inside_fraction")) << name;
        // The median of two runs lies between them (numpy's interpolation).
        const double a = j["per_run"][0]["variants"][name]["heading_error_deg"][1].get<double>();
        const double b = j["per_run"][1]["variants"][name]["heading_error_deg"][1].get<double>();
        EXPECT_DOUBLE_EQ(v["heading_error_deg"][1].get<double>(), 0.5 * (a + b)) << name;
    }
}

TEST(NavCli, BadInputIsRefusedWithItsReason) {
    TempDir dir("nav_cli_bad");
    make_logs(dir);
    // Aids drawn from a truth the run does not have.
    RunResult r = run_driftlab({"nav", dir.file("sg.csv"), "--aid", "odometry"}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("--truth"), std::string::npos) << r.output;
    // A truth of another run.
    ASSERT_EQ(run_driftlab(
                  {"hil", "--trajectory", "figure8", "--duration", "100", "--period", "0.2", "-o", dir.file("f8.csv")},
                  dir.path())
                  .exit_code,
              0);
    r = run_driftlab({"nav", dir.file("sg.csv"), "--truth", dir.file("f8.truth.csv")}, dir.path());
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("f8.truth.csv"), std::string::npos) << r.output;
    // A drift file that is not fit's or allan's output.
    std::ofstream(dir.file("bad.json")) << "{\"channels\": {\"gyro\": {}}}";
    r = run_driftlab({"nav", dir.file("sg.csv"), "--drift", dir.file("bad.json")}, dir.path());
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("bad.json"), std::string::npos) << r.output;
    // A JSON file past kMaxJsonFileBytes is refused before it is held (docs/security.md), here a 17 MiB array.
    {
        std::ofstream big(dir.file("big.json"));
        big << "[" << std::string(17 << 20, ' ') << "]";
    }
    r = run_driftlab({"nav", dir.file("sg.csv"), "--drift", dir.file("big.json")}, dir.path());
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("big.json: longer than 16 MiB"), std::string::npos) << r.output;
    // An unknown aid.
    r = run_driftlab({"nav", dir.file("sg.csv"), "--aid", "gps"}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.output;
    // A table without the channels: no gyro; one horizontal accelerometer without the other.
    std::ofstream table(dir.file("acc.csv"));
    table << "t_s,ax,ay\n";
    for (int i = 0; i < 200; ++i) table << i * 0.1 << "," << 0.001 * (i % 7) << "," << 0.002 * (i % 5) << "\n";
    table.close();
    r = run_driftlab({"nav", dir.file("acc.csv"), "--tau0", "0.1", "--as", "accel_x=ax:0.001"}, dir.path());
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("no gyro"), std::string::npos) << r.output;
}

TEST(NavCli, ADriftFileFromFitJsonWorksAsFitFrom) {
    TempDir dir("nav_cli_fitjson");
    make_logs(dir);
    const RunResult fit = run_driftlab({"fit", dir.file("rest.csv"), "--json"}, dir.path());
    ASSERT_EQ(fit.exit_code, 0) << fit.output;
    std::ofstream(dir.file("fit.json")) << fit.output.substr(fit.output.find('{'));
    const nlohmann::json a = parse_json(run_driftlab(
        {"nav", dir.file("sg.csv"), "--truth", dir.file("sg.truth.csv"), "--drift", dir.file("fit.json"), "--json"},
        dir.path()));
    const nlohmann::json b = parse_json(run_driftlab(
        {"nav", dir.file("sg.csv"), "--truth", dir.file("sg.truth.csv"), "--fit-from", dir.file("rest.csv"), "--json"},
        dir.path()));
    // The same eq. 1 (one fitter): the forward dead reckoning is the same to the fit's printed digits.
    EXPECT_NEAR(a["variants"]["forward"]["heading_error_deg"][2].get<double>(),
                b["variants"]["forward"]["heading_error_deg"][2].get<double>(), 1e-3);
    EXPECT_FALSE(a["notes"].empty());  // a fit file has no Allan terms: said
}

// A real gyro standing still (docs/nav.md §Real recordings): eq. 1 fitted on its first 800 s and applied to the
// 1580 s held out drifts the heading several times less than the constant bias raw takes from that stretch's start;
// a gyro-only table navigates the heading alone.
TEST(NavCli, OnARealStaticGyroTheDriftFittedOnTheFirstPartCutsTheHeldOutDrift) {
    const std::string real = std::string(DRIFTLAB_SHARED_DIR) + "/data/real/gyro2_x.txt";
    if (!std::filesystem::exists(real)) GTEST_SKIP() << real << " not found (../shared is absent)";
    TempDir dir("nav_real");
    const nlohmann::json j =
        parse_json(run_driftlab({"nav", real, "--tau0", "0.01", "--as", "gyro=col1:0.00875", "--at-rest", "--fit-from",
                                 real, "--fit-to", "800", "--from", "800", "--json"},
                                dir.path()));
    EXPECT_EQ(j["nees_dof"], 1);
    const double raw = j["variants"]["raw"]["heading_drift_deg_per_min"].get<double>();
    const double fwd = j["variants"]["forward"]["heading_drift_deg_per_min"].get<double>();
    EXPECT_GT(raw, 1.0);  // the warm-up the provenance describes: 1.10 deg/s falling to 0.64 deg/s
    EXPECT_LT(fwd * 5.0, raw);
    EXPECT_TRUE(j["variants"]["raw"]["position_error_m"][0].is_null());  // no accelerometers: no position
}

}  // namespace
}  // namespace driftlab::e2e
