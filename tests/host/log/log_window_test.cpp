// rows_between(): the rows of a time window, every column cut alike and the gap events among them renumbered.
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

}  // namespace
}  // namespace driftlab::host
