// The ground truth reader and its row-by-row match with the log (host/log/truth_file.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "host/log/truth_file.hpp"
#include "host/util/error.hpp"
#include "tests/support/temp_dir.hpp"

namespace driftlab::host {
namespace {

const std::string kHeader =
    "# driftlab ground truth v1\n# trajectory: figure8\n# rest_before_s: 5\n"
    "t_s,x_m,y_m,heading_deg,speed_mps,yaw_rate_dps,accel_x_g,accel_y_g,accel_z_g\n";

std::string rows(int n) {
    std::string out;
    for (int k = 0; k < n; ++k) out += std::to_string(0.1 * (k + 1)) + ",0,0,0,0," + std::to_string(k) + ",0,0,1\n";
    return out;
}

LogData log_of(int n) {
    LogData log;
    log.source_name = "r.csv";
    for (int k = 0; k < n; ++k) log.t_s.push_back(0.1 * (k + 1));
    return log;
}

std::string error_of(const TruthFile& truth, const LogData& log, bool cut) {
    try {
        match_truth_rows(truth, log, cut);
    } catch (const DataError& e) {
        return e.what();
    }
    return "";
}

TEST(TruthFile, ReadsTheColumnsAndTheTrajectoryLines) {
    const TruthFile t = read_truth_file(test_support::write_temp_file("ok", kHeader + rows(3)));
    EXPECT_EQ(t.trajectory, "figure8");
    EXPECT_EQ(t.rest_before_s, 5.0);
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t.yaw_rate_dps[2], 2.0);
    EXPECT_EQ(t.lines[0], 5u);
    EXPECT_EQ(match_truth_rows(t, log_of(3), false), (std::vector<std::size_t>{0, 1, 2}));
}

TEST(TruthFile, AMissingColumnOrTimesThatDoNotIncreaseNameTheLine) {
    const std::string no_yaw = test_support::write_temp_file("noyaw", "t_s,x_m\n0.1,0\n0.2,0\n");
    EXPECT_THROW(
        {
            try {
                read_truth_file(no_yaw);
            } catch (const DataError& e) {
                EXPECT_NE(std::string(e.what()).find("no column 'y_m'"), std::string::npos) << e.what();
                throw;
            }
        },
        DataError);
    const std::string back =
        test_support::write_temp_file("back", kHeader + "0.2,0,0,0,0,0,0,0,1\n0.1,0,0,0,0,0,0,0,1\n");
    try {
        read_truth_file(back);
        FAIL() << "times going back are accepted";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find(back + ":6:"), std::string::npos) << e.what();
    }
}

TEST(TruthFile, ATruthThatPartsFromItsLogNamesWhere) {
    const TruthFile t = read_truth_file(test_support::write_temp_file("match", kHeader + rows(5)));
    // The truth goes on after the log: its line 8 (row 4) has no log row.
    EXPECT_NE(error_of(t, log_of(3), false).find(":8: the truth goes on after the last row"), std::string::npos);
    // A log row the truth lacks.
    EXPECT_NE(error_of(t, log_of(6), false).find("no row at 0.600000 s"), std::string::npos);
    // A cut log (rows left out) may skip truth rows; not one as recorded.
    LogData cut = log_of(5);
    cut.t_s.erase(cut.t_s.begin() + 1);
    EXPECT_EQ(error_of(t, cut, true), "");
    EXPECT_NE(error_of(t, cut, false).find(":6: the truth's row at 0.200000 s has no row in r.csv"), std::string::npos);
}

}  // namespace
}  // namespace driftlab::host
