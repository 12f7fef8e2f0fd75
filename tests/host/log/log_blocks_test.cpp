// A long log's rows are read in blocks of whole lines, each parsed in two halves at once: what it reads, the first
// bad line it names and its cut last line must be those of reading line by line, wherever a block or a half ends.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "host/log/log_reader.hpp"
#include "host/util/error.hpp"
#include "host/util/input_file.hpp"
#include "tests/support/data_error.hpp"

namespace driftlab::host {
namespace {

const std::string kLongHead = "# driftlab-log: 1\n# source: test\nt_s,seq,gyro,accel_x,accel_y,accel_z,temp_c\n";
constexpr std::size_t kLongHeadLines = 3;
// About 20 MB of rows: three blocks of 8 MB, each split in two.
constexpr std::size_t kLongRows = 700000;

std::string long_row(std::size_t k) {
    return std::to_string(k + 1) + ".5," + std::to_string(k) + "," + std::to_string(k % 1024) + ",512,513," +
           std::to_string(1023 - k % 1024) + ",25.25";
}

// Every row; a `# gap:` comment before each row in `gaps`; CR LF line ends on the rows in `crlf`.
std::string long_log(const std::vector<std::size_t>& gaps = {}, const std::vector<std::size_t>& crlf = {}) {
    std::string text = kLongHead;
    text.reserve(kLongRows * 32);
    for (std::size_t k = 0; k < kLongRows; ++k) {
        if (std::find(gaps.begin(), gaps.end(), k) != gaps.end()) text += "# gap: lost link\n";
        text += long_row(k);
        text += std::find(crlf.begin(), crlf.end(), k) != crlf.end() ? "\r\n" : "\n";
    }
    return text;
}

// The file line of row k of long_log() without comments.
std::uint64_t long_line_of(std::size_t k) { return kLongHeadLines + k + 1; }

LogData parse_long(const std::string& text, const ReadOptions& options = {}) {
    std::istringstream in(text);
    return parse_log(in, "long.csv", options);
}

std::string long_rejection(const std::string& text) {
    return test_support::data_error_of([&] { parse_long(text); });
}

// Rows in each block and half, every value where it was written, gap comments counted to the row after them.
TEST(LogBlocks, ALongLogReadsEveryRowWithItsGapsWhereverTheBlocksEnd) {
    const std::vector<std::size_t> gaps = {1, 150000, 290000, 420000, 699999};
    const LogData log = parse_long(long_log(gaps, {5, 300000, 650000}));
    ASSERT_EQ(log.size(), kLongRows);
    for (std::size_t k = 0; k < kLongRows; k += 997) {
        EXPECT_EQ(log.t_s[k], static_cast<double>(k + 1) + 0.5) << k;
        EXPECT_EQ(log.seq[k], k) << k;
        EXPECT_EQ(log.counts[0][k], static_cast<double>(k % 1024)) << k;
        EXPECT_EQ(log.counts[3][k], static_cast<double>(1023 - k % 1024)) << k;
    }
    EXPECT_EQ(log.counts[2].back(), 513.0);
    ASSERT_EQ(log.optional_columns.at("temp_c").size(), kLongRows);
    EXPECT_EQ(log.optional_columns.at("temp_c").back(), 25.25);
    ASSERT_EQ(log.gaps.size(), gaps.size());
    for (std::size_t i = 0; i < gaps.size(); ++i) {
        EXPECT_EQ(log.gaps[i].before_row, gaps[i]);
        EXPECT_EQ(log.gaps[i].line, long_line_of(gaps[i]) + i);  // each comment before it is a line too
        EXPECT_EQ(log.gaps[i].text, "lost link");
    }
}

// A bad value in the second half of a later block, t_s going back at another place: each is named at its line, and
// of two the earlier in the file.
TEST(LogBlocks, TheFirstBadLineInTheFileIsNamedAtItsLine) {
    for (std::size_t bad : {10u, 200000u, 380000u, 699999u}) {
        std::string text = long_log();
        const std::string good = long_row(bad) + "\n";
        std::string broken = good;
        broken.replace(broken.find(",512,"), 5, ",5x2,");
        text.replace(text.find(good), good.size(), broken);
        EXPECT_NE(
            long_rejection(text).find("long.csv:" + std::to_string(long_line_of(bad)) + ": field 4 (accel_x) '5x2'"),
            std::string::npos)
            << bad;
    }
    std::string twice = long_log();
    const std::string later = long_row(450000) + "\n", earlier = long_row(360000) + "\n";
    twice.replace(twice.find(later), later.size(), "x" + later);
    twice.replace(twice.find(earlier), earlier.size(), "1.0," + earlier.substr(earlier.find(',') + 1));
    EXPECT_NE(long_rejection(twice).find("long.csv:" + std::to_string(long_line_of(360000)) + ": t_s 1 is not after"),
              std::string::npos);
}

TEST(LogBlocks, ALongLogsCutLastLineIsRefusedOrDroppedAsALineByLineReadDid) {
    std::string text = long_log();
    text += "700001.5,700000,3,5";  // cut: no newline, too few fields
    EXPECT_NE(
        long_rejection(text).find("long.csv:" + std::to_string(long_line_of(kLongRows)) + ": truncated last line"),
        std::string::npos);
    ReadOptions drop;
    drop.drop_truncated_tail = true;
    const LogData log = parse_long(text, drop);
    EXPECT_EQ(log.size(), kLongRows);
    EXPECT_EQ(log.dropped_cut_line, long_line_of(kLongRows));
}

// A line that runs on past a block is measured whole: one longer than the limit is refused at its line, as the line
// reader refuses it, however many blocks it spans.
TEST(LogBlocks, ALineLongerThanTheLimitAmongTheRowsIsRefusedAtItsLine) {
    std::string text =
        kLongHead + long_row(0) + "\n" + std::string(kMaxLineBytes + 10, '7') + "\n" + long_row(1) + "\n";
    EXPECT_NE(long_rejection(text).find("long.csv:" + std::to_string(long_line_of(1)) + ": a line longer than"),
              std::string::npos);
}

}  // namespace
}  // namespace driftlab::host
