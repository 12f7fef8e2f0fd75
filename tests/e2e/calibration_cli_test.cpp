// The board's own compensation end to end through `driftlab`: a Fig. 3 run calibrated and run again compensated
// (the gyro's first and last ten minutes), the analyses saying a log is compensated and `calibrate` refusing to do it
// twice, `upload` into a board on a pseudo-terminal and `record` reading the state back, and bad calibration files.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "host/log/log_reader.hpp"
#include "tests/e2e/e2e_support.hpp"

namespace driftlab::e2e {
namespace {

constexpr int kDataErrorExit = 3;

// Mean of the gyro over the rows with t_s in [from, to].
double gyro_mean(const host::LogData& log, double from, double to) {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < log.size(); ++i) {
        if (log.t_s[i] < from || log.t_s[i] > to) continue;
        sum += log.channel(Channel::gyro)[i];
        ++n;
    }
    EXPECT_GT(n, 500u);
    return sum / static_cast<double>(n);
}

double first_to_last_ten_minutes(const host::LogData& log) {
    const double end = log.t_s.back();
    return gyro_mean(log, end - 600.0, end) - gyro_mean(log, 0.0, 600.0);
}

TEST(CalibrationCli, ACompensatedFig3RunHoldsTheGyroBetweenItsFirstAndLastTenMinutes) {
    TempDir dir("calfig3");
    ASSERT_EQ(
        run_driftlab({"hil", "--preset", "fig3", "--seed", "1", "-o", dir.file("earlier.csv")}, dir.path()).exit_code,
        0);
    const RunResult cal = run_driftlab({"calibrate", dir.file("earlier.csv"), "-o", dir.file("cal.json")}, dir.path());
    ASSERT_EQ(cal.exit_code, 0) << cal.output;
    EXPECT_NE(cal.output.find("512 (mid-scale)"), std::string::npos) << cal.output;
    for (const char* cal_opt : {"", "--cal"}) {
        std::vector<std::string> args = {"hil", "--preset", "fig3", "--seed", "2", "-o", dir.file("run.csv")};
        if (*cal_opt) args.insert(args.end(), {cal_opt, dir.file("cal.json")});
        const RunResult r = run_driftlab(args, dir.path());
        ASSERT_EQ(r.exit_code, 0) << r.output;
        const host::LogData log = host::read_log(dir.file("run.csv"));
        const double drift = first_to_last_ten_minutes(log);
        if (*cal_opt) {
            EXPECT_EQ(log.metadata.get("cal_state"), "active");
            EXPECT_LE(std::fabs(drift), 0.3) << "compensated";
            EXPECT_NEAR(gyro_mean(log, 0.0, 600.0), 512.0, 0.3);  // referred to zero as calibrate chose
        } else {
            EXPECT_EQ(log.metadata.get("cal_state"), "none");
            EXPECT_GE(drift, 1.2) << "uncompensated";  // Table 1's C1 = 3 counts, T = 411 s
        }
    }
    // The analyses read the flag: fit says what it fits, calibrate will not do it twice.
    const RunResult fit = run_driftlab({"fit", dir.file("run.csv")}, dir.path());
    EXPECT_EQ(fit.exit_code, 0) << fit.output;
    EXPECT_NE(fit.output.find("compensated on board (calibration "), std::string::npos) << fit.output;
    const RunResult twice = run_driftlab({"calibrate", dir.file("run.csv"), "-o", dir.file("again.json")}, dir.path());
    EXPECT_EQ(twice.exit_code, kDataErrorExit) << twice.output;
    EXPECT_NE(twice.output.find("would compensate twice"), std::string::npos) << twice.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("again.json")));
}

TEST(CalibrationCli, UploadIntoABoardIsReadBackAndTheRecordingSaysItIsCompensated) {
    TempDir dir("calupload");
    ASSERT_EQ(
        run_driftlab({"hil", "--preset", "fig3", "--seed", "3", "-o", dir.file("earlier.csv")}, dir.path()).exit_code,
        0);
    ASSERT_EQ(
        run_driftlab({"calibrate", dir.file("earlier.csv"), "-o", dir.file("cal.json"), "--id", "321"}, dir.path())
            .exit_code,
        0);
    BoardThread board(paced_board(20.0, 600.0));
    const RunResult up = run_driftlab({"upload", "--port", board.path(), "--cal", dir.file("cal.json")}, dir.path());
    ASSERT_EQ(up.exit_code, 0) << up.output;
    EXPECT_NE(up.output.find("calibration 321 stored, read back and in use"), std::string::npos) << up.output;
    const RunResult rec = run_driftlab(
        {"record", "--port", board.path(), "--poll", "0.1", "--duration", "2", "-o", dir.file("rec.csv")}, dir.path());
    ASSERT_EQ(rec.exit_code, 0) << rec.output;
    const host::LogData log = host::read_log(dir.file("rec.csv"));
    EXPECT_EQ(log.metadata.get("cal_state"), "active");
    EXPECT_EQ(log.metadata.get_int("cal_id"), 321);
    const RunResult clear = run_driftlab({"upload", "--port", board.path(), "--clear"}, dir.path());
    ASSERT_EQ(clear.exit_code, 0) << clear.output;
    const RunResult after = run_driftlab(
        {"record", "--port", board.path(), "--poll", "0.1", "--duration", "1", "-o", dir.file("after.csv")},
        dir.path());
    ASSERT_EQ(after.exit_code, 0) << after.output;
    EXPECT_EQ(host::read_log(dir.file("after.csv")).metadata.get("cal_state"), "none");
}

TEST(CalibrationCli, ACalibrationFileOutsideWhatABoardTakesIsRefusedNamingTheKey) {
    TempDir dir("calbad");
    ASSERT_EQ(run_driftlab({"hil", "--preset", "fig3", "--seed", "4", "--duration", "1200", "-o", dir.file("e.csv")},
                           dir.path())
                  .exit_code,
              0);
    ASSERT_EQ(run_driftlab({"calibrate", dir.file("e.csv"), "-o", dir.file("cal.json")}, dir.path()).exit_code, 0);
    std::string text;
    {
        std::ifstream in(dir.file("cal.json"));
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    // T of the gyro cut to 5 s, below the board's 60 s.
    const std::size_t t = text.find("\"T\": ", text.find("\"gyro\""));
    ASSERT_NE(t, std::string::npos);
    std::string short_t = text;
    short_t.replace(t + 5, text.find(',', t) - t - 5, "5.0");
    std::ofstream(dir.file("short.json")) << short_t;
    const RunResult r =
        run_driftlab({"hil", "--preset", "fig3", "--cal", dir.file("short.json"), "-o", dir.file("x.csv")}, dir.path());
    EXPECT_EQ(r.exit_code, kDataErrorExit) << r.output;
    EXPECT_NE(r.output.find(dir.file("short.json") + ": gyro: T = 5 s, a board takes T from 60 to 34000 s"),
              std::string::npos)
        << r.output;
    std::ofstream(dir.file("notjson.json")) << "C1 = 3\n";
    const RunResult bad =
        run_driftlab({"upload", "--port", "/dev/null", "--cal", dir.file("notjson.json")}, dir.path());
    EXPECT_EQ(bad.exit_code, kDataErrorExit) << bad.output;
    EXPECT_NE(bad.output.find(dir.file("notjson.json") + ": not JSON"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace driftlab::e2e
