// Canonical log writer and reader: round trip, every rejection with its line number (docs/log-format.md).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "host/log/log_reader.hpp"
#include "host/log/log_writer.hpp"
#include "host/util/error.hpp"
#include "tests/support/data_error.hpp"

namespace driftlab::host {
namespace {

std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("driftlab_log_test_" + name)).string();
}

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

LogData parse(const std::string& text, const ReadOptions& options = {}) {
    std::istringstream in(text);
    return parse_log(in, "mem.csv", options);
}

/// Parses `text` and returns the DataError message; fails the test when nothing is thrown.
std::string rejection(const std::string& text) {
    return test_support::data_error_of([&] { parse(text); }, text);
}

const std::string kHead = "# driftlab-log: 1\n# source: test\nt_s,seq,gyro,accel_x,accel_y,accel_z\n";

TEST(LogIo, WriterOutputReadsBackExactlyWithMetadataGapsAndOptionalColumns) {
    const std::string path = temp_path("roundtrip.csv");
    LogMetadata meta;
    meta.set("source", std::string("sim"));
    meta.set("sample_period_s", 0.1);
    meta.set("window", std::int64_t{16});
    std::vector<LogRow> rows;
    for (int k = 0; k < 50; ++k) {
        LogRow r;
        r.t_s = 0.1 * k + 1.0 / 3.0;
        r.seq = static_cast<std::uint64_t>(k + (k >= 20 ? 3 : 0));
        r.counts = {505.0 + k / 7.0, 470.125, 474.0 - k * 1e-3, 622.0 + std::sqrt(2.0)};
        r.optional_values = {505.0, static_cast<double>(k % 2)};
        rows.push_back(r);
    }
    {
        LogWriter w(path, meta, {"raw_gyro", "flags"});
        for (int k = 0; k < 50; ++k) {
            if (k == 20) w.write_gap("link lost 0.3 s");
            w.write_row(rows[static_cast<std::size_t>(k)]);
        }
        w.close();
    }
    const LogData log = read_log(path);
    ASSERT_EQ(log.size(), 50u);
    EXPECT_EQ(log.metadata.get("source"), "sim");
    EXPECT_DOUBLE_EQ(*log.metadata.get_double("sample_period_s"), 0.1);
    EXPECT_EQ(*log.metadata.get_int("window"), 16);
    EXPECT_EQ(log.metadata.entries().size(), 3u);
    for (std::size_t k = 0; k < 50; ++k) {
        EXPECT_EQ(log.t_s[k], rows[k].t_s);  // exact: shortest round-trip text
        EXPECT_EQ(log.seq[k], rows[k].seq);
        for (std::size_t c = 0; c < kChannelCount; ++c) EXPECT_EQ(log.counts[c][k], rows[k].counts[c]);
        EXPECT_EQ(log.optional_columns.at("raw_gyro")[k], 505.0);
        EXPECT_EQ(log.optional_columns.at("flags")[k], static_cast<double>(k % 2));
    }
    ASSERT_EQ(log.gaps.size(), 1u);
    EXPECT_EQ(log.gaps[0].before_row, 20u);
    EXPECT_EQ(log.gaps[0].text, "link lost 0.3 s");
    EXPECT_EQ(log.gaps[0].line, 3u + 1u + 1u + 20u + 1u);  // magic, 3 metadata, header, 20 rows, then the gap
    std::filesystem::remove(path);
}

// The analyses hold the log for their whole run; grown row by row, 1025 rows would have held room for 2048.
TEST(LogIo, TheColumnsReadHoldNoRoomBeyondTheirRows) {
    std::string text = "# driftlab-log: 1\nt_s,seq,gyro,accel_x,accel_y,accel_z,raw_gyro\n";
    constexpr std::size_t kRows = 1025;
    for (std::size_t k = 0; k < kRows; ++k)
        text += std::to_string(k + 1) + "," + std::to_string(k) + ",512,500,501,620,512\n";
    const LogData log = parse(text);
    ASSERT_EQ(log.size(), kRows);
    EXPECT_EQ(log.t_s.capacity(), kRows);
    EXPECT_EQ(log.seq.capacity(), kRows);
    for (std::size_t c = 0; c < kChannelCount; ++c) EXPECT_EQ(log.counts[c].capacity(), kRows) << kChannelNames[c];
    ASSERT_EQ(log.optional_columns.at("raw_gyro").size(), kRows);
    EXPECT_EQ(log.optional_columns.at("raw_gyro").capacity(), kRows);
}

TEST(LogIo, WriterFlushesOnlyWholeLines) {
    const std::string path = temp_path("whole_lines.csv");
    LogMetadata meta;
    LogWriter w(path, meta);
    w.set_flush_interval(std::chrono::milliseconds(0));
    LogRow r;
    for (int k = 0; k < 5; ++k) {
        r.t_s = k;
        w.write_row(r);
        const std::string text = read_file(path);  // what a concurrent reader sees now
        ASSERT_FALSE(text.empty());
        EXPECT_EQ(text.back(), '\n');
        EXPECT_EQ(parse(text).size(), static_cast<std::size_t>(k + 1));
    }
    w.close();
    std::filesystem::remove(path);
}

TEST(LogIo, WriterRefusesRowsItsReaderWouldReject) {
    const std::string path = temp_path("refuse.csv");
    LogWriter w(path, LogMetadata{});
    LogRow r;
    r.t_s = 1.0;
    w.write_row(r);
    EXPECT_THROW(w.write_row(r), UsageError);  // same t_s
    {
        LogWriter early(temp_path("early.csv"), LogMetadata{});
        LogRow before = r;
        before.t_s = -1.0;
        EXPECT_THROW(early.write_row(before), UsageError);  // before power-on
    }
    r.t_s = 2.0;
    r.counts[1] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(w.write_row(r), UsageError);
    r.counts[1] = 0.0;
    r.optional_values = {1.0};
    EXPECT_THROW(w.write_row(r), UsageError);  // no optional columns declared
    EXPECT_THROW(LogWriter(temp_path("x.csv"), LogMetadata{}, {"colour"}), UsageError);
    // The reader refuses a repeat
    EXPECT_THROW(LogWriter(temp_path("x.csv"), LogMetadata{}, {"tick", "tick"}), UsageError);
    {
        LogMetadata m;
        m.set("adc_bits", std::int64_t{10});
        LogWriter bounded(temp_path("x.csv"), m);
        r.optional_values.clear();
        r.counts = {1365.0, -342.0, 0.0, 1023.0};
        bounded.write_row(r);
        r.t_s = 3.0;
        r.counts[2] = 1365.5;
        EXPECT_THROW(bounded.write_row(r), UsageError);  // beyond the 10-bit converter's reach
        LogWriter with_raw(temp_path("x.csv"), m, {"raw_gyro"});
        r.counts[2] = 0.0;
        r.optional_values = {-1.0};
        with_raw.write_row(r);
        r.t_s = 4.0;
        r.optional_values = {1024.0};
        EXPECT_THROW(with_raw.write_row(r), UsageError);  // no 10-bit code
    }
    w.close();
    std::filesystem::remove(path);
    std::filesystem::remove(temp_path("x.csv"));
}

TEST(LogIo, UnknownColumnsAreIgnoredAndColumnOrderIsFree) {
    const LogData log = parse(
        "# driftlab-log: 1\n"
        "accel_z,note,seq,t_s,gyro,accel_x,accel_y,raw_gyro\n"
        "622,hello,0,0.5,505,470,474,506\n"
        "623,world,1,1.5,506,471,475,507\n");
    ASSERT_EQ(log.size(), 2u);
    EXPECT_EQ(log.t_s[1], 1.5);
    EXPECT_EQ(log.channel(Channel::gyro)[1], 506.0);
    EXPECT_EQ(log.channel(Channel::accel_z)[0], 622.0);
    EXPECT_EQ(log.optional_columns.at("raw_gyro")[1], 507.0);
    EXPECT_FALSE(log.has_column("note"));
}

TEST(LogIo, EachRejectionNamesTheLine) {
    EXPECT_NE(rejection("").find("empty file"), std::string::npos);
    EXPECT_NE(rejection("t_s,seq,gyro,accel_x,accel_y,accel_z\n0,0,1,2,3,4\n").find("mem.csv:1: not a driftlab log"),
              std::string::npos);
    EXPECT_NE(rejection("# driftlab-log: 2\n").find("mem.csv:1: log format version '2'"), std::string::npos);
    EXPECT_NE(rejection("# driftlab-log: 1\n0,0,1,2,3,4\n").find("mem.csv:2: missing header"), std::string::npos);
    EXPECT_NE(rejection("# driftlab-log: 1\n# source: x\n").find("mem.csv:2: missing header"), std::string::npos);
    EXPECT_NE(rejection("# driftlab-log: 1\nt_s,seq,gyro,accel_x,accel_y\n")
                  .find("mem.csv:2: header lacks the "
                        "required column 'accel_z'"),
              std::string::npos);
    EXPECT_NE(rejection(kHead).find("mem.csv:3: log has a header but no data rows"), std::string::npos);
    EXPECT_NE(rejection(kHead + "0,0,1,2,3,4\n" + "t_s,seq,gyro,accel_x,accel_y,accel_z\n")
                  .find("mem.csv:5: duplicate header (the first is on line 3)"),
              std::string::npos);
    EXPECT_NE(rejection(kHead + "0,0,1,2,3\n").find("mem.csv:4: expected 6 fields"), std::string::npos);
    EXPECT_NE(rejection(kHead + "0,0,1,2,3,4\n1,1,nan,2,3,4\n").find("mem.csv:5: field 3 (gyro) 'nan': not finite"),
              std::string::npos);
    EXPECT_NE(rejection(kHead + "0,0,1,inf,3,4\n").find("mem.csv:4: field 4 (accel_x) 'inf': not finite"),
              std::string::npos);
    EXPECT_NE(rejection(kHead + "0,0,1,2,3,abc\n").find("mem.csv:4: field 6 (accel_z) 'abc': not a number"),
              std::string::npos);
    EXPECT_NE(rejection(kHead + "0,0,1,2,,4\n").find("mem.csv:4: field 5 (accel_y) '': empty field"),
              std::string::npos);
    EXPECT_NE(rejection(kHead + "0,0,1,2,3,4\n2,1,1,2,3,4\n1.5,2,1,2,3,4\n")
                  .find("mem.csv:6: t_s 1.5 is not after the previous row's 2"),
              std::string::npos);
    EXPECT_NE(rejection(kHead + "0,0,1,2,3,4\n0,1,1,2,3,4\n").find("mem.csv:5: t_s 0 is not after"), std::string::npos);
    const std::string flags_head = kHead.substr(0, kHead.size() - 1) + ",sat_flags\n";
    EXPECT_EQ(parse(flags_head + "0,0,1,2,3,4,15\n").optional_columns.at("sat_flags")[0], 15.0);
    EXPECT_NE(rejection(flags_head + "0,0,1,2,3,4,1.5\n")
                  .find("mem.csv:4: field 7 (sat_flags) '1.5': not a set of channel bits"),
              std::string::npos);
    EXPECT_NE(rejection(flags_head + "0,0,1,2,3,4,16\n").find("field 7 (sat_flags) '16'"), std::string::npos);
    // t_s counts from power-on: eq. 1 fitted to negative times had given NaN residuals and a misleading message.
    EXPECT_NE(rejection(kHead + "-0.5,0,1,2,3,4\n").find("mem.csv:4: t_s -0.5 is before power-on"), std::string::npos);
    EXPECT_NE(rejection(kHead + "0,-1,1,2,3,4\n").find("mem.csv:4: field 2 (seq) '-1': not a non-negative integer"),
              std::string::npos);
    EXPECT_NE(rejection("# driftlab-log: 1\n# a: 1\n# a: 2\n").find("mem.csv:3: metadata key 'a' appears twice"),
              std::string::npos);
    // A carriage return inside a value (found by the log_reader fuzzer) had escaped as a usage error, exit 2.
    EXPECT_NE(rejection("# driftlab-log: 1\n# fit_order: 0\r0\n")
                  .find("mem.csv:2: metadata value of 'fit_order' "
                        "holds a carriage return"),
              std::string::npos);
}

// A 10-bit converter's least-squares estimate reaches from -1023/3 to 4 x 1023/3 counts (the order-1 weights at the
// window's end sum to 4/3 above zero and -1/3 below), a count more either side for the Q8 rounding.
TEST(LogIo, AValueBeyondTheConvertersReachIsRejectedWhenTheLogNamesItsResolution) {
    const std::string head = "# driftlab-log: 1\n# adc_bits: 10\nt_s,seq,gyro,accel_x,accel_y,accel_z\n";
    const LogData edge = parse(head + "0,0,-342,1365,512,-341.5\n");  // the reach's ends are values it can hold
    EXPECT_EQ(edge.channel(Channel::accel_x)[0], 1365.0);
    EXPECT_NE(
        rejection(head + "0,0,1,2,3,4\n1,1,512,1e308,3,4\n")
            .find("mem.csv:5: field 4 (accel_x) '1e308': beyond the 10-bit converter's reach (-342 to 1365 counts)"),
        std::string::npos);
    EXPECT_NE(rejection(head + "0,0,-342.01,2,3,4\n").find("mem.csv:4: field 3 (gyro)"), std::string::npos);
    EXPECT_NE(rejection("# driftlab-log: 1\n# adc_bits: 12\nt_s,seq,gyro,accel_x,accel_y,accel_z\n0,0,1,2,3,5461.5\n")
                  .find("field 6 (accel_z) '5461.5': beyond the 12-bit converter's reach (-1366 to 5461 counts)"),
              std::string::npos);
    // Raw codes are the converter's own: 0 to 2^bits - 1 and integral, or -1 where the row's RAW frame was lost.
    const std::string raw_head = "# driftlab-log: 1\n# adc_bits: 10\nt_s,seq,gyro,accel_x,accel_y,accel_z,raw_gyro\n";
    EXPECT_EQ(parse(raw_head + "0,0,1,2,3,4,1023\n1,2,1,2,3,4,-1\n").optional_columns.at("raw_gyro")[1], -1.0);
    EXPECT_NE(rejection(raw_head + "0,0,1,2,3,4,1024\n")
                  .find("mem.csv:4: field 7 (raw_gyro) '1024': not a code of the 10-bit converter (0 to 1023, or -1 "
                        "for a lost RAW frame)"),
              std::string::npos);
    EXPECT_NE(rejection(raw_head + "0,0,1,2,3,4,511.5\n").find("field 7 (raw_gyro) '511.5'"), std::string::npos);
    // Without the resolution no bound is known: the value is kept, unless the reader is told what to assume.
    EXPECT_EQ(parse(kHead + "0,0,1e9,2,3,4\n").channel(Channel::gyro)[0], 1e9);
    ReadOptions assume;
    assume.assumed_adc_bits = 10;
    try {
        parse(kHead + "0,0,1e9,2,3,4\n", assume);
        ADD_FAILURE() << "1e9 accepted with 10 bits assumed";
    } catch (const DataError& e) {
        EXPECT_NE(
            std::string(e.what()).find("mem.csv:4: field 3 (gyro) '1e9': beyond the 10-bit converter's reach (-342 to "
                                       "1365 counts; the metadata names no adc_bits, 10 assumed)"),
            std::string::npos)
            << e.what();
    }
    // The metadata's own resolution wins over the assumption.
    EXPECT_EQ(parse("# driftlab-log: 1\n# adc_bits: 12\nt_s,seq,gyro,accel_x,accel_y,accel_z\n0,0,4000,2,3,4\n", assume)
                  .channel(Channel::gyro)[0],
              4000.0);
}

TEST(LogIo, MetadataKeysKnowTheirLines) {
    const LogData log = parse(
        "# driftlab-log: 1\n# a free comment\n# window: 8\n\n# fit_order: 1\n"
        "t_s,seq,gyro,accel_x,accel_y,accel_z\n0,0,1,2,3,4\n");
    EXPECT_EQ(log.metadata.line_of("window"), 3u);
    EXPECT_EQ(log.metadata.line_of("fit_order"), 5u);
    EXPECT_EQ(log.metadata.line_of("absent"), 0u);
}

TEST(LogIo, TruncatedLastLineIsReportedOrDroppedOnRequest) {
    const std::string cut = kHead + "0,0,1,2,3,4\n1,1,1,2,3,4\n2,2,1,2,3";  // recorder killed mid-line
    const std::string message = rejection(cut);
    EXPECT_NE(message.find("mem.csv:6: truncated last line (no newline"), std::string::npos) << message;
    EXPECT_NE(message.find("interrupted): expected 6 fields (as the header), got 5"), std::string::npos) << message;
    const std::string complete_fields = kHead + "0,0,1,2,3,4\n1,1,1,2,3,4.5";  // fields complete but maybe cut
    EXPECT_NE(rejection(complete_fields).find("mem.csv:5: truncated last line"), std::string::npos);

    ReadOptions drop;
    drop.drop_truncated_tail = true;
    const LogData a = parse(cut, drop);
    EXPECT_EQ(a.size(), 2u);
    EXPECT_EQ(a.dropped_cut_line, 6u);
    const LogData b = parse(complete_fields, drop);
    EXPECT_EQ(b.size(), 1u);
    EXPECT_EQ(b.dropped_cut_line, 5u);
    EXPECT_EQ(parse(kHead + "0,0,1,2,3,4\n", drop).dropped_cut_line, 0u);  // a whole last line is kept and not named
}

TEST(LogIo, CommentsBlankLinesAndCrLfAreAccepted) {
    const LogData log = parse(
        "# driftlab-log: 1\r\n# model: paper_default\r\n\r\n# a free comment\r\n"
        "t_s,seq,gyro,accel_x,accel_y,accel_z\r\n0,0,1,2,3,4\r\n# note: operator\r\n"
        "# gap: reconnect after 2 s\r\n3,9,1,2,3,4\r\n");
    EXPECT_EQ(log.size(), 2u);
    EXPECT_EQ(log.metadata.get("model"), "paper_default");
    ASSERT_EQ(log.gaps.size(), 1u);
    EXPECT_EQ(log.gaps[0].before_row, 1u);
    EXPECT_EQ(log.gaps[0].line, 8u);
    EXPECT_EQ(log.seq[1], 9u);
}

// What tells a canonical log from a plain table (fit, allan, gap) is the magic line as the reader takes it: after
// blank lines, with blanks around the key; a table's name line or a comment is not one.
TEST(LogIo, ALogIsKnownByItsMagicLineAsTheReaderTakesIt) {
    const auto starts = [](const std::string& text) {
        std::istringstream in(text);
        return starts_as_log(in);
    };
    EXPECT_TRUE(starts("# driftlab-log: 1\nt_s,seq\n"));
    EXPECT_TRUE(starts("\n  \r\n# driftlab-log: 1\n"));
    EXPECT_TRUE(starts("#driftlab-log : 2\n"));  // another version is still a log, which the reader then refuses
    EXPECT_FALSE(starts("# a comment\n# driftlab-log: 1\n"));
    // A damaged magic line is a log the reader refuses with its reason, not a plain table.
    EXPECT_TRUE(starts("# driftlab-log 1\nt_s,seq\n"));
    EXPECT_NE(
        rejection("# driftlab-log 1\nt_s,seq,gyro,accel_x,accel_y,accel_z\n0,0,1,2,3,4\n")
            .find("mem.csv:1: not a driftlab log: the first line must be '# driftlab-log: 1', got '# driftlab-log 1'"),
        std::string::npos);
    EXPECT_FALSE(starts("t_s,gx\n0,1\n"));
    EXPECT_FALSE(starts(""));
    const LogData log = parse("\n# driftlab-log: 1\nt_s,seq,gyro,accel_x,accel_y,accel_z\n0,0,1,2,3,4\n");
    EXPECT_EQ(log.size(), 1u);
}

TEST(LogIo, MissingFileIsADataError) { EXPECT_THROW(read_log(temp_path("does_not_exist.csv")), DataError); }

}  // namespace
}  // namespace driftlab::host
