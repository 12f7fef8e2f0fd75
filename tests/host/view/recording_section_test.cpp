// The report's recording table: every row a recorded log's header gives, worded for a reader comparing against a
// datasheet, and for a log with almost no header only the rows its data give (no "unknown" padding).
#include "host/view/recording_section.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "host/fit/file_analysis.hpp"
#include "host/view/html_report.hpp"
#include "tests/support/temp_dir.hpp"

namespace driftlab::host::view {
namespace {

using test_support::TempDir;
using Rows = std::vector<std::pair<std::string, std::string>>;

/// A log in `dir` whose metadata lines are `header`, of `rows` rows `period_s` apart from t = `first_s`, with a
/// `# gap:` line after row `gap_after` (none when negative).
std::string write_log(const TempDir& dir, const std::string& header, int rows, double first_s, double period_s,
                      int gap_after = -1) {
    const std::string path = dir.file("log.csv");
    std::ofstream out(path);
    out << "# driftlab-log: 1\n" << header << "t_s,seq,gyro,accel_x,accel_y,accel_z\n";
    for (int k = 0; k < rows; ++k) {
        // A rise and a zig-zag, so that every channel can be fitted.
        const double v = 505.0 + 3.0 * k / rows + 0.3 * ((k * 7) % 5);
        out << first_s + period_s * k << ',' << k << ',' << v << ',' << v << ',' << v << ',' << v << '\n';
        if (k == gap_after) out << "# gap: link lost\n";
    }
    return path;
}

/// The channels row of a log with all four channels: 90/512 deg/s and 19.14 mm/s^2 per count (host/util/units.hpp).
const std::string kFourChannels =
    "gyro, accel_x, accel_y, accel_z [counts]; a count is 0.17578 deg/s (gyro), 19.14 mm/s^2 (accelerometer)";

fit::FileAnalysis analyse(const std::string& path) {
    fit::FileAnalysisRequest request;
    request.path = path;
    return fit::analyse_file(request);
}

TEST(RecordingSection, ARecordedLogShowsItsBoardFirmwareRateAndSmoothing) {
    const TempDir dir("recording_full");
    const std::string header =
        "# source: record\n# firmware_version: 0.1.0\n# protocol_version: 1\n# board_id: 3\n# sample_period_s: 0.1\n"
        "# conversions_per_output: 16\n# window: 16\n# fit_order: 1\n# mode: stream\n# adc_bits: 10\n# vref_v: 5\n"
        "# tick_hz: 250000\n# port: /dev/ttyUSB0\n# baud: 115200\n# start_utc: 2026-11-27T21:00:00Z\n";
    const fit::FileAnalysis file = analyse(write_log(dir, header, 1200, 0.5, 0.1, 600));
    ASSERT_TRUE(file.log.has_value());
    // 1200 rows 0.1 s apart from 0.5 s: the last at 120.4 s, 119.9 s after the first.
    const Rows expected = {
        {"source", "record: a board, recorded over its serial link"},
        {"board", "id 3, port /dev/ttyUSB0, 115200 baud"},
        {"firmware", "version 0.1.0, protocol 1"},
        {"log format", "driftlab log, format 1"},
        {"start", "2026-11-27T21:00:00Z"},
        {"duration", "119.9 s (2 min 0 s), t_s 0.5 to 120.4 s after power-on"},
        {"samples", "1200, 1 link gap (# gap: lines)"},
        {"output rate", "10 Hz (sample_period_s 0.1 s, stream mode)"},
        {"smoothing", "on-board least squares of order 1 (a line) over 16 conversions, 16 conversions per output"},
        {"converter", "10-bit, 5 V reference, 250000 Hz tick"},
        {"channels", kFourChannels},
    };
    EXPECT_EQ(recording_rows(*file.log), expected);
}

// Under hil no board takes part: the id is the one the emulated firmware was built for, and the row says so.
TEST(RecordingSection, AHilLogsBoardRowSaysTheBoardIsEmulated) {
    fit::LogOverview log;
    log.metadata.set("source", std::string("hil"));
    log.metadata.set("board_id", static_cast<std::int64_t>(1));
    log.rows = 2;
    log.last_t_s = 1.0;
    const Rows rows = recording_rows(log);
    ASSERT_GE(rows.size(), 2u);
    EXPECT_EQ(rows[1], (std::pair<std::string, std::string>("board (emulated)", "firmware built for id 1")));
}

// A log with only its magic line: the rows its data give and nothing padded; the rate is measured, and says so.
TEST(RecordingSection, ASparseHeaderGivesOnlyTheRowsTheDataGive) {
    const TempDir dir("recording_sparse");
    const fit::FileAnalysis file = analyse(write_log(dir, "", 600, 1.0, 2.0));
    ASSERT_TRUE(file.log.has_value());
    const Rows expected = {
        {"log format", "driftlab log, format 1"},
        {"duration", "1198 s (19 min 58 s), t_s 1 to 1199 s after power-on"},
        {"samples", "600"},
        {"output rate", "0.5 Hz (the rows' mean spacing; the header names no sample_period_s)"},
        {"channels", kFourChannels},
    };
    EXPECT_EQ(recording_rows(*file.log), expected);
    ReportOptions options;
    options.plots = false;
    const std::string html = render_html_report(file, options);
    // At the top: before the fit.
    const auto recording = html.find("<h2>Recording</h2>");
    ASSERT_NE(recording, std::string::npos);
    EXPECT_LT(recording, html.find("<h2>Turn-on drift"));
    EXPECT_NE(html.find("<tr><th>samples</th><td>600</td></tr>"), std::string::npos) << html;
    EXPECT_EQ(html.find("unknown"), std::string::npos);
}

// Metadata is free text from a file: it is escaped, never markup.
TEST(RecordingSection, MetadataIsEscaped) {
    fit::LogOverview log;
    log.metadata.set("source", std::string("<script>"));
    log.rows = 2;
    log.last_t_s = 1.0;
    EXPECT_NE(recording_section(log).find("<td>&lt;script&gt;</td>"), std::string::npos) << recording_section(log);
}

// A plain table has no header to show: no recording table.
TEST(RecordingSection, APlainTableHasNone) {
    const TempDir dir("recording_plain");
    const std::string path = dir.file("t.txt");
    std::ofstream out(path);
    for (int k = 0; k < 100; ++k) out << 1.0 + 0.01 * k + 0.1 * ((k * 7) % 5) << '\n';
    out.close();
    const fit::FileAnalysis file = analyse(path);
    EXPECT_FALSE(file.log.has_value());
    ReportOptions options;
    options.plots = false;
    EXPECT_EQ(render_html_report(file, options).find("Recording"), std::string::npos);
}

}  // namespace
}  // namespace driftlab::host::view
