// `driftlab hil --trajectory` as a user runs it: the log and its ground truth, checked against each other and against
// the model's own figures (docs/sim.md §Motion), and a trajectory the command refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "e2e_support.hpp"
#include "host/log/log_reader.hpp"
#include "host/log/numeric_table.hpp"

namespace driftlab::e2e {
namespace {

// A unit without noise or drift: eq. 1 is the constant C2 = 505 counts, so a reading is the front end's alone.
const std::string kQuietGyro = "[channels.gyro]\nraw_noise_std_dps = 0.0\ndrift_c1_counts = 0.0\n";

struct TurntableRun {
    host::LogData log;
    host::NumericTable truth;
    std::vector<double> truth_rate;
};

TurntableRun run_turntable(const TempDir& dir, const std::string& model) {
    std::ofstream(dir.file("m.toml")) << model;
    const RunResult r = run_driftlab({"hil", "--model", dir.file("m.toml"), "--trajectory", "turntable", "--duration",
                                      "400", "--period", "0.1", "-o", dir.file("t.csv")},
                                     dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    TurntableRun run{host::read_log(dir.file("t.csv")), host::read_numeric_table(dir.file("t.truth.csv")), {}};
    run.truth_rate = run.truth.columns[run.truth.column_index("yaw_rate_dps")];
    return run;
}

// Rows on a plateau: the true rate the same as 3 s before, so the least-squares window holds that rate alone.
std::vector<std::size_t> plateau_rows(const std::vector<double>& rate) {
    std::vector<std::size_t> rows;
    for (std::size_t k = 30; k < rate.size(); ++k)
        if (rate[k] == rate[k - 30]) rows.push_back(k);
    return rows;
}

// Independent check: the gyro's counts regressed on the truth's yaw rate give the front end's 512/90 counts per deg/s
// times (1 + the scale-factor error), and eq. 1's C2 at zero rate.
TEST(MotionCli, ATurntableLogRegressedOnItsTruthRecoversScaleFactorAndBias) {
    TempDir dir("turntable");
    const TurntableRun run =
        run_turntable(dir, kQuietGyro + "\n[effects.scale_factor]\nerror_pct = [2.0, 0.0, 0.0, 0.0]\n");
    ASSERT_EQ(run.truth.rows(), run.log.size()) << "one truth row per log row";
    for (std::size_t k = 0; k < run.log.size(); ++k)
        ASSERT_EQ(run.truth.columns[run.truth.column_index("t_s")][k], run.log.t_s[k]);
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t k : plateau_rows(run.truth_rate)) {
        const double x = run.truth_rate[k], y = run.log.channel(Channel::gyro)[k];
        n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    ASSERT_GT(n, 2000);
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx), bias = (sy - slope * sx) / n;
    EXPECT_NEAR(slope / (512.0 / 90.0), 1.02, 0.001);
    EXPECT_NEAR(bias, 505.0, 0.1);
}

// A gyro of ±60 deg/s span on a turntable that reaches 80: the clipped outputs sit at the converter's rails, the
// firmware flags them, and `fit` and `allan` say where.
TEST(MotionCli, BeyondItsRangeTheGyroSitsAtTheRailAndFitSaysWhere) {
    TempDir dir("turntable_sat");
    const TurntableRun run = run_turntable(dir, kQuietGyro + "span_dps = 60.0\n");
    const std::vector<double>& gyro = run.log.channel(Channel::gyro);
    const std::vector<double>& flags = run.log.optional_columns.at("sat_flags");
    int high = 0, low = 0;
    for (std::size_t k : plateau_rows(run.truth_rate)) {
        // 505 + 80 x 512/60 is beyond 1023; 505 - 60 x 512/60 below 0.
        const bool beyond = std::abs(run.truth_rate[k]) * 512.0 / 60.0 > (run.truth_rate[k] > 0 ? 1023 - 505 : 505);
        EXPECT_EQ(beyond, host::flags_saturation(flags[k], 0)) << "t = " << run.log.t_s[k];
        if (!beyond) continue;
        EXPECT_EQ(gyro[k], run.truth_rate[k] > 0 ? 1023.0 : 0.0) << "t = " << run.log.t_s[k];
        (run.truth_rate[k] > 0 ? high : low) += 1;
    }
    EXPECT_GT(high, 100);
    EXPECT_GT(low, 100);
    for (const char* command : {"fit", "allan"}) {
        const RunResult r = run_driftlab({command, dir.file("t.csv"), "--channel", "gyro"}, dir.path());
        EXPECT_NE(r.output.find("note: gyro saturated (sat_flags) in "), std::string::npos) << command << r.output;
    }
}

// gap's replicates are a unit at rest: a log in motion without its truth is refused naming its trajectory's line,
// not read as a gap.
TEST(MotionCli, GapRefusesALogInMotion) {
    TempDir dir("gapmotion");
    ASSERT_EQ(run_driftlab({"hil", "--trajectory", "square", "--duration", "60", "-o", dir.file("s.csv")}, dir.path())
                  .exit_code,
              0);
    const RunResult gap = run_driftlab({"gap", dir.file("s.csv")}, dir.path());
    EXPECT_EQ(gap.exit_code, 3) << gap.output;
    EXPECT_NE(gap.output.find(dir.file("s.csv") + ":"), std::string::npos) << gap.output;
    EXPECT_NE(gap.output.find("recorded in motion (trajectory square)"), std::string::npos) << gap.output;
    EXPECT_NE(gap.output.find("give its ground truth with --truth"), std::string::npos) << gap.output;
}

TEST(MotionCli, AnUnknownTrajectoryOrABadFileIsRefusedAndNothingIsWritten) {
    TempDir dir("badtrajectory");
    const RunResult unknown =
        run_driftlab({"hil", "--trajectory", "sqaure", "--duration", "10", "-o", dir.file("a.csv")}, dir.path());
    EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
    EXPECT_NE(unknown.output.find("unknown trajectory 'sqaure'"), std::string::npos) << unknown.output;
    std::ofstream(dir.file("p.csv")) << "t_s,speed_mps,yaw_rate_dps\n0,0,0\n1,0,0\n1,0,5\n";
    const RunResult bad = run_driftlab(
        {"hil", "--trajectory", dir.file("p.csv"), "--duration", "10", "-o", dir.file("b.csv")}, dir.path());
    EXPECT_EQ(bad.exit_code, 5) << bad.output;
    EXPECT_NE(bad.output.find(dir.file("p.csv") + ":4: t_s:"), std::string::npos) << bad.output;
    for (const char* f : {"a.csv", "a.truth.csv", "b.csv", "b.truth.csv"})
        EXPECT_FALSE(std::filesystem::exists(dir.file(f))) << f;
    EXPECT_EQ(
        run_driftlab({"hil", "--rest-before", "5", "--duration", "10", "-o", dir.file("c.csv")}, dir.path()).exit_code,
        2);
}

}  // namespace
}  // namespace driftlab::e2e
