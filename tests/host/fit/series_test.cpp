// Series from a plain table: the time column times the rows and is not itself a series.
#include "host/fit/series.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "host/io/capture.hpp"

#include "host/log/numeric_table.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::fit {
namespace {

TEST(Series, NamingTheTimeColumnIsRefused) {
    NumericTable table;
    table.source_name = "table.txt";
    table.names = {"t_s", "gyro"};
    table.columns = {{0.0, 1.0, 2.0}, {1.0, 2.0, 3.0}};
    EXPECT_EQ(series_from_table(table, {"gyro"}, "", 1.0).size(), 1u);
    try {
        series_from_table(table, {"t_s"}, "", 1.0);
        ADD_FAILURE() << "the time column was taken as a series";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("'t_s' is the time column of table.txt"), std::string::npos) << e.what();
    }
}

TEST(Series, AnUnknownChannelOfALogIsRefusedListingTheChannels) {
    try {
        series_from_log(LogData{}, {"gyro", "accel_w"});
        ADD_FAILURE() << "accel_w was taken as a channel";
    } catch (const UsageError& e) {
        EXPECT_EQ(std::string(e.what()), "unknown channel 'accel_w' (channels: gyro, accel_x, accel_y, accel_z)");
    }
}

// Read as a table, a capture failed on its header's second line ("field 1 'port:': not a number"): every analysis
// command now names `decode`, whose input it is.
TEST(Series, ARawCaptureIsRefusedNamingDecode) {
    const std::string path =
        (std::filesystem::temp_directory_path() / ("driftlab_series_" + std::to_string(::getpid()) + ".cap")).string();
    io::CaptureWriter(path, {{"port", "/dev/ttyUSB0"}}).write_event("start");
    try {
        load_series(path, {});
        ADD_FAILURE() << "a capture was read as a table";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find(path + ":1: a raw capture"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("driftlab decode " + path), std::string::npos) << e.what();
    }
    std::filesystem::remove(path);
}

// is_canonical_log reads the head once for both checks: a log whose magic is its first line (which the capture
// check has already read) and one after blank lines are logs; a table is not; a missing file is named.
TEST(Series, OneOpenOfTheHeadTellsALogFromATable) {
    const std::string path =
        (std::filesystem::temp_directory_path() / ("driftlab_head_" + std::to_string(::getpid()) + ".csv")).string();
    const auto head_of = [&path](const std::string& text) {
        std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
        return is_canonical_log(path);
    };
    EXPECT_TRUE(head_of("# driftlab-log: 1\nt_s,seq\n"));
    EXPECT_TRUE(head_of("\n  \r\n# driftlab-log: 1\n"));
    EXPECT_FALSE(head_of("t_s gyro\n0 1\n"));
    EXPECT_FALSE(head_of("# driftlab-capture: 1\n"));  // a comment, not a capture's magic: a table's
    std::filesystem::remove(path);
    EXPECT_THROW(is_canonical_log(path), DataError);
}

// --from/--to and --exclude windows: both ends of each are taken (in range) or left out (in a window), the raw codes
// go with their rows, overlapping windows are the union, and a window that holds no row in range names itself.
TEST(Series, RowsKeptAreInRangeAndOutsideEveryWindowWithTheirRawCodes) {
    Series s;
    s.name = "gyro";
    s.source = "log.csv";
    for (int k = 0; k < 10; ++k) {
        s.t_s.push_back(k);
        s.values.push_back(100.0 + k);
        s.raw_values.push_back(200.0 + k);
    }
    const Series kept = rows_kept(s, 1.0, 8.0, {{3.0, 4.0, "--exclude"}, {3.5, 5.0, "--exclude"}});
    EXPECT_EQ(kept.t_s, (std::vector<double>{1, 2, 6, 7, 8}));
    EXPECT_EQ(kept.values, (std::vector<double>{101, 102, 106, 107, 108}));
    EXPECT_EQ(kept.raw_values, (std::vector<double>{201, 202, 206, 207, 208}));
    EXPECT_EQ(rows_kept(s, -1.0, 20.0).t_s, s.t_s);
    EXPECT_EQ(rows_in(s.t_s, {3.0, 5.0, "--exclude"}, 1.0, 8.0), 3u);
    EXPECT_EQ(rows_in(s.t_s, {7.5, 9.5, "--exclude"}, 1.0, 8.0), 1u);  // row 9 is beyond the range
    // Row 9 exists, but not in the range kept.
    try {
        rows_kept(s, 1.0, 8.0, {{8.5, 9.5, "--exclude"}});
        ADD_FAILURE() << "a window without a row in range was taken";
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(),
                     "log.csv: series 'gyro': --exclude 8.5:9.5 holds no row (the series' rows run from 0 s to 9 s)");
    }
}

// fit and allan say alike why a range left too few rows, and where the rows are (the span of the whole series, not
// of the range); a series without rows has no span to give.
TEST(Series, TooFewKeptNamesTheCountTheSeriesSpanAndTheNeed) {
    Series s;
    s.name = "gx";
    s.t_s = {0.25, 1.25, 2999.5};
    s.values = {1, 2, 3};
    EXPECT_EQ(
        too_few_kept(s, 1, "the fit", 20),
        "series 'gx': 1 sample in the selected time range (the series' rows run from 0.25 s to 2999.5 s); the fit "
        "needs at least 20");
    s.t_s.clear();
    EXPECT_EQ(too_few_kept(s, 0, "the Allan deviation", 2),
              "series 'gx': 0 samples in the selected time range; the Allan deviation needs at least 2");
}

// The notes agree with rows_kept: the range's count and ends are those of the rows it keeps before any window, and
// each window counts the rows in range it takes, overlaps counted for each.
TEST(Series, SelectionNotesCountWhatTheRangeKeptAndEachWindowTook) {
    Series s;
    for (int k = 0; k < 10; ++k) {
        s.t_s.push_back(0.5 * k);
        s.values.push_back(k);
    }
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(selection_notes(s.t_s, -inf, inf, {}).empty());
    EXPECT_EQ(selection_notes(s.t_s, 1.0, 3.2, {{2.0, 2.5, "--exclude"}, {2.4, 9.0, "--exclude"}}),
              (std::vector<std::string>{"--from 1 --to 3.2 kept 5 of 10 rows, t = 1 s to 3 s",
                                        "--exclude 2:2.5 left out 2 rows", "--exclude 2.4:9 left out 2 rows"}));
    EXPECT_EQ(rows_kept(s, 1.0, 3.2).t_s, (std::vector<double>{1, 1.5, 2, 2.5, 3}));
    EXPECT_EQ(selection_notes(s.t_s, 4.5, inf, {}),
              (std::vector<std::string>{"--from 4.5 kept 1 of 10 rows, t = 4.5 s"}));
    EXPECT_EQ(selection_notes(s.t_s, -inf, 0.2, {}), (std::vector<std::string>{"--to 0.2 kept 1 of 10 rows, t = 0 s"}));
    // A range without rows is refused where the rows are cut, with their span: no note.
    EXPECT_TRUE(selection_notes(s.t_s, 5.0, 6.0, {}).empty());
}

}  // namespace
}  // namespace driftlab::host::fit
