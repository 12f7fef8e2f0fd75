// The recorder's live status line: the newest row as a person watching the recording reads it.
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "host/io/status_line.hpp"

namespace driftlab::host::io {
namespace {

// Table 1's settled codes: the gyro 7 counts below mid-scale is -1.23 deg/s (90/512 deg/s a count); the
// accelerometer axes are given as their counts (their g per count is the paper's open question), where a g figure
// from mid-scale had read Z's 622 counts at rest as +2.15 g.
TEST(StatusLine, TheGyroInDegreesPerSecondTheAccelerometerInCounts) {
    AssemblyStats s;
    s.rows = 123;
    s.last_counts = {505.0, 470.0, 474.0, 622.0};
    const std::string line = format_status_line(s, 12.3, std::nullopt);
    EXPECT_NE(line.find("rows 123"), std::string::npos) << line;
    EXPECT_NE(line.find("gyro -1.23 deg/s"), std::string::npos) << line;
    EXPECT_NE(line.find("accel 470.0 474.0 622.0 counts"), std::string::npos) << line;
    EXPECT_EQ(line.find(" g "), std::string::npos) << line;
}

// While the port is away: how long since, and when the next reopen attempt comes (it had said only "PORT LOST,
// reconnecting..." and changed only with the wall time, once per back-off step).
TEST(StatusLine, ThePortAwaySaysSinceWhenAndTheNextAttempt) {
    AssemblyStats s;
    s.rows = 123;
    s.last_counts = {505.0, 470.0, 474.0, 622.0};
    const std::string line = format_status_line(s, 12.3, LinkLoss{3.24, 4, 1.76});
    EXPECT_NE(line.find("rows 123"), std::string::npos) << line;
    EXPECT_NE(line.find("PORT LOST 3.2 s ago, reconnect attempt 4 in 1.8 s"), std::string::npos) << line;
    EXPECT_EQ(line.find("gyro"), std::string::npos) << line;  // the newest values are not current
}

// The gap line names the clock of each figure: the last row's t_s is the board's, the loss's time and length the
// host's. It had read "link lost after t_s=5.500 (3.990 s into the recording), reconnected after 11.759 s, 6 attempts",
// two clocks as bare seconds side by side.
TEST(StatusLine, TheGapLineNamesTheClockOfEachFigure) {
    EXPECT_EQ(link_lost_gap(5.5, 3.99, 11.759, 6),
              "link lost after t_s=5.500 (board clock), 3.990 s into the recording (host clock); reconnected after "
              "11.759 s (host clock), 6 attempts");
    EXPECT_EQ(link_lost_gap(std::nullopt, 0.5, 0.25, 1),
              "link lost before the first row, 0.500 s into the recording (host clock); reconnected after 0.250 s "
              "(host clock), 1 attempt");
}

}  // namespace
}  // namespace driftlab::host::io
