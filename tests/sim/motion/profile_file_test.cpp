// A user's trajectory file (sim/motion/profile_file.hpp): read as the profile it states, and every malformed or
// unphysical file refused naming the file and its line.
#include "sim/motion/profile_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "sim/motion/trajectories.hpp"
#include "sim/sim_error.hpp"
#include "tests/support/temp_dir.hpp"

namespace driftlab::sim {
namespace {

std::string write(const test_support::TempDir& dir, const std::string& text) {
    const std::string path = dir.file("profile.csv");
    std::ofstream(path) << text;
    return path;
}

TEST(ProfileFile, RowsBecomeLinearSegmentsInTheHeadersColumnOrder) {
    test_support::TempDir dir("profile");
    const std::string path = write(dir,
                                   "# a start, a left curve, a stop\n"
                                   "yaw_rate_dps speed_mps t_s\n"
                                   "0 0 0\n"
                                   "0,1.0,2\n"
                                   "30, 1.0, 3\n"
                                   "\n"
                                   "30 0 5\n");
    const auto segments = read_profile_file(path);
    ASSERT_EQ(segments.size(), 3u);
    EXPECT_DOUBLE_EQ(segments[0].accel_mps2, 0.5);
    EXPECT_DOUBLE_EQ(segments[1].yaw_accel_dps2, 30.0);
    EXPECT_DOUBLE_EQ(segments[2].accel_mps2, -0.5);
    const Trajectory t = make_trajectory(path, 100.0, 4.0, 1);
    EXPECT_NEAR(t.state_at(4.0 + 2.0).x_m, 1.0, 1e-12);  // 2 s from rest at 0.5 m/s^2
    EXPECT_NEAR(t.state_at(4.0 + 4.0).input.yaw_rate_dps, 30.0, 1e-12);
    EXPECT_NEAR(t.state_at(50.0).input.yaw_rate_dps, 30.0, 1e-12) << "keeps its last row's rates";
}

TEST(ProfileFile, AMalformedOrUnphysicalFileIsRefusedNamingItsLine) {
    test_support::TempDir dir("profile");
    const std::string header = "t_s,speed_mps,yaw_rate_dps\n";
    const struct {
        std::string text, where, says;
    } cases[] = {
        {"0,0,0\n1,1,0\n", ":1: header", "expected the columns t_s, speed_mps and yaw_rate_dps"},
        {"t_s,speed\n", ":1: header", "expected the columns"},
        {header + "0,0,0\n1,x,0\n", ":3: speed_mps", "expected a finite number, got 'x'"},
        {header + "0,0,0\n1,nan,0\n", ":3: speed_mps", "expected a finite number"},
        {header + "0,0,0\n1,0\n", ":3: row", "expected 3 fields, got 2"},
        {header + "1,0,0\n2,0,0\n", ":2: t_s", "the first row's time must be 0"},
        {header + "0,0,0\n1,0,0\n1,0,0\n", ":4: t_s", "is not after the previous row's"},
        {header + "0,0,0\n1,0,1500\n", ":3: yaw_rate_dps", "beyond ±1000 deg/s"},
        {header + "0,0,0\n0.01,1.5,0\n", ":3: speed_mps", "exceeds 10 g"},
        {header + "0,0,0\n", ": rows", "at least two rows"},
        {"# nothing\n", ": header", "no header line"},
    };
    for (const auto& c : cases) {
        const std::string path = write(dir, c.text);
        try {
            read_profile_file(path);
            ADD_FAILURE() << "accepted: " << c.text;
        } catch (const ModelFileError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind(path + c.where, 0), 0u) << what;
            EXPECT_NE(what.find(c.says), std::string::npos) << what;
        }
    }
    EXPECT_THROW(read_profile_file(dir.file("none.csv")), ModelFileError);
}

}  // namespace
}  // namespace driftlab::sim
