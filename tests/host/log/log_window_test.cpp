// rows_between() and rows_outside(): the rows of a time window, or of the log less some windows, every column cut
// alike, the gap events among the rows kept renumbered, and each window left out recorded where the rows join.
#include <gtest/gtest.h>

#include "host/log/log_window.hpp"
#include "host/util/error.hpp"

namespace driftlab::host {
namespace {

LogData ten_rows() {
    LogData log;
    log.source_name = "ten.csv";
    for (int k = 0; k < 10; ++k) {
        log.t_s.push_back(1.0 + k);
        log.seq.push_back(static_cast<std::uint64_t>(k));
        for (auto& column : log.counts) column.push_back(500.0 + k);
        log.optional_columns["sat_flags"].push_back(k == 6 ? 1.0 : 0.0);
    }
    log.gaps = {{2, 12, "before row 2"}, {7, 18, "before row 7"}};
    return log;
}

TEST(LogWindow, KeepsTheRowsOfTheWindowInEveryColumn) {
    const LogData w = rows_between(ten_rows(), 4.0, 8.0);  // t = 4..8: rows 3..7
    ASSERT_EQ(w.size(), 5u);
    EXPECT_DOUBLE_EQ(w.t_s.front(), 4.0);
    EXPECT_DOUBLE_EQ(w.t_s.back(), 8.0);
    EXPECT_EQ(w.seq.front(), 3u);
    for (const auto& column : w.counts) EXPECT_DOUBLE_EQ(column.front(), 503.0);
    ASSERT_EQ(w.optional_columns.at("sat_flags").size(), 5u);
    EXPECT_DOUBLE_EQ(w.optional_columns.at("sat_flags")[3], 1.0);  // row 6
    // The gap before row 2 lies outside; the one before row 7 is now before row 4.
    ASSERT_EQ(w.gaps.size(), 1u);
    EXPECT_EQ(w.gaps[0].before_row, 4u);
    EXPECT_EQ(w.gaps[0].line, 18u);
    EXPECT_EQ(w.source_name, "ten.csv");
}

TEST(LogWindow, AnOpenEndKeepsEverythingOnThatSide) {
    EXPECT_EQ(rows_between(ten_rows(), 7.5, INFINITY).size(), 3u);  // t = 8, 9, 10
    EXPECT_EQ(rows_between(ten_rows(), -INFINITY, 1.0).size(), 1u);
}

TEST(LogWindow, AWindowWithoutRowsIsRefusedNamingTheLogAndItsSpan) {
    try {
        rows_between(ten_rows(), 20.0, 30.0);
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(), "ten.csv: no row lies between 20 s and 30 s (its rows run from 1 s to 10 s)");
    }
}

TEST(LogWindow, AStretchLeftOutJoinsTheRowsEitherSideAndIsRecordedThere) {
    const LogData w = rows_outside(ten_rows(), {{3.5, 5.0, "--exclude"}});  // t = 4, 5: rows 3 and 4
    ASSERT_EQ(w.size(), 8u);
    EXPECT_EQ(w.t_s, (std::vector<double>{1, 2, 3, 6, 7, 8, 9, 10}));
    EXPECT_EQ(w.seq[3], 5u);
    for (const auto& column : w.counts) EXPECT_DOUBLE_EQ(column[3], 505.0);
    EXPECT_DOUBLE_EQ(w.optional_columns.at("sat_flags")[4], 1.0);  // row 6
    ASSERT_EQ(w.cuts.size(), 1u);
    EXPECT_EQ(w.cuts[0].before_row, 3u);  // between t = 3 and t = 6
    EXPECT_EQ(w.cuts[0].rows, 2u);
    EXPECT_DOUBLE_EQ(w.cuts[0].from_s, 3.5);
    EXPECT_DOUBLE_EQ(w.cuts[0].to_s, 5.0);
    // Both gap events lie between kept rows: before row 2 stays, before row 7 is now before row 5.
    ASSERT_EQ(w.gaps.size(), 2u);
    EXPECT_EQ(w.gaps[0].before_row, 2u);
    EXPECT_EQ(w.gaps[1].before_row, 5u);
}

TEST(LogWindow, OverlappingStretchesAreOneCutAndAnEarlierWindowKeepsItsCut) {
    const LogData w = rows_outside(
        ten_rows(),
        {{7.5, 9.0, "--exclude"}, {2.0, 2.5, "--exclude"}, {6.5, 8.0, "--exclude-saturated"}});  // rows 1; rows 6, 7, 8
    EXPECT_EQ(w.t_s, (std::vector<double>{1, 3, 4, 5, 6, 10}));
    ASSERT_EQ(w.cuts.size(), 2u);
    EXPECT_EQ(w.cuts[0].before_row, 1u);
    EXPECT_EQ(w.cuts[0].rows, 1u);
    EXPECT_EQ(w.cuts[1].before_row, 5u);
    EXPECT_EQ(w.cuts[1].rows, 3u);
    EXPECT_DOUBLE_EQ(w.cuts[1].from_s, 6.5);
    EXPECT_DOUBLE_EQ(w.cuts[1].to_s, 9.0);
    EXPECT_EQ(w.cuts[0].by, "--exclude");
    EXPECT_EQ(w.cuts[1].by, "--exclude-saturated, --exclude");  // merged: both options that asked for it
    EXPECT_TRUE(w.gaps.empty());                                // before row 2 and row 7: each next to a row left out
    // A window of the rows kept then keeps the cut inside it, renumbered.
    const LogData later = rows_between(w, 2.5, 10.0);
    ASSERT_EQ(later.cuts.size(), 1u);
    EXPECT_EQ(later.cuts[0].before_row, 4u);
}

TEST(LogWindow, AStretchWithoutRowsOrOneThatLeavesNoneIsRefused) {
    try {
        rows_outside(ten_rows(), {{4.2, 4.8, "--exclude"}});
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(), "ten.csv: no row lies between 4.2 s and 4.8 s (its rows run from 1 s to 10 s)");
    }
    // A window that misses is refused even inside another one, and so is a reversed one.
    try {
        rows_outside(ten_rows(), {{3.0, 6.0, "--exclude"}, {4.2, 4.8, "--exclude"}});
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(), "ten.csv: no row lies between 4.2 s and 4.8 s (its rows run from 1 s to 10 s)");
    }
    try {
        rows_outside(ten_rows(), {{3.0, 8.0, "--exclude"}, {6.0, 5.0, "--exclude"}});
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(), "ten.csv: no row lies between 6 s and 5 s (its rows run from 1 s to 10 s)");
    }
    try {
        rows_outside(ten_rows(), {{0.0, 5.0, "--exclude"}, {5.0, 11.0, "--exclude"}});
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(), "ten.csv: no row is left once the windows are left out (its rows run from 1 s to 10 s)");
    }
}

TEST(LogWindow, SaturatedStretchesAreTheFlaggedRunsOfTheChannelsAskedWidenedByTheMargin) {
    LogData log = ten_rows();  // t = 1..10; sat_flags: gyro (bit 0) in row 6
    auto& flags = log.optional_columns["sat_flags"];
    flags[1] = 8.0;             // accel_z in row 1
    flags[7] = flags[8] = 3.0;  // gyro and accel_x in rows 7, 8: one run with row 6
    const std::array<bool, kChannelCount> gyro{true, false, false, false};
    const auto g = saturated_stretches(log, gyro, 0.5);
    ASSERT_EQ(g.size(), 1u);
    EXPECT_DOUBLE_EQ(g[0].from_s, 6.5);  // row 6 is t = 7
    EXPECT_DOUBLE_EQ(g[0].to_s, 9.5);
    const std::array<bool, kChannelCount> all{true, true, true, true};
    const auto a = saturated_stretches(log, all, 0.0);
    ASSERT_EQ(a.size(), 2u);
    EXPECT_DOUBLE_EQ(a[0].from_s, 2.0);
    EXPECT_DOUBLE_EQ(a[0].to_s, 2.0);
    const LogData kept = rows_outside(log, a);
    EXPECT_EQ(kept.size(), 6u);  // rows 0, 2..5, 9
    EXPECT_EQ(kept.cuts.size(), 2u);
    const std::array<bool, kChannelCount> accel_y{false, false, true, false};
    EXPECT_TRUE(saturated_stretches(log, accel_y, 1.0).empty());
    log.optional_columns.erase("sat_flags");
    try {
        saturated_stretches(log, all, 0.0);
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find("ten.csv: no sat_flags column"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace driftlab::host
