// A long plain table's lines after its head are read in blocks, each parsed in two halves at once (line_blocks.hpp):
// every value, line number and comment, and the first bad line named, must be those of reading line by line,
// wherever a block or a half ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "host/log/numeric_table.hpp"
#include "host/util/error.hpp"
#include "tests/support/data_error.hpp"

namespace driftlab::host {
namespace {

// About 20 MB: three blocks of 8 MB, each split in two.
constexpr std::size_t kTableRows = 900000;
constexpr std::uint64_t kTableHeadLines = 2;  // a comment and the name line

std::string table_row(std::size_t k) { return std::to_string(k) + ".25, " + std::to_string(k % 977) + " -1.5e-3"; }

// Every row; a comment before each row in `comments`.
std::string long_table(const std::vector<std::size_t>& comments = {}) {
    std::string text = "# three columns\nt x y\n";
    text.reserve(kTableRows * 24);
    for (std::size_t k = 0; k < kTableRows; ++k) {
        if (std::find(comments.begin(), comments.end(), k) != comments.end())
            text += "# before row " + std::to_string(k) + "\n";
        text += table_row(k) + (k % 5000 == 7 ? "\r\n" : "\n");
    }
    return text;
}

NumericTable parse_table(const std::string& text) {
    std::istringstream in(text);
    return parse_numeric_table(in, "long.txt");
}

std::string table_rejection(const std::string& text) {
    return test_support::data_error_of([&] { parse_table(text); });
}

// The file line of row k of long_table() without comments.
std::uint64_t table_line_of(std::size_t k) { return kTableHeadLines + k + 1; }

TEST(TableBlocks, ALongTableReadsEveryValueLineAndCommentWhereverTheBlocksEnd) {
    const std::vector<std::size_t> comments = {3, 250000, 420000, 899999};
    const NumericTable t = parse_table(long_table(comments));
    ASSERT_EQ(t.rows(), kTableRows);
    ASSERT_EQ(t.columns.size(), 3u);
    EXPECT_EQ(t.names, (std::vector<std::string>{"t", "x", "y"}));
    for (std::size_t k = 0; k < kTableRows; ++k) {
        ASSERT_EQ(t.columns[0][k], static_cast<double>(k) + 0.25) << k;
        ASSERT_EQ(t.columns[1][k], static_cast<double>(k % 977)) << k;
        ASSERT_EQ(t.columns[2][k], -1.5e-3) << k;
        const auto before = static_cast<std::uint64_t>(std::count_if(
            comments.begin(), comments.end(), [&](std::size_t c) { return c <= k; }));  // comment lines above
        ASSERT_EQ(t.row_lines[k], table_line_of(k) + before) << k;
    }
    ASSERT_EQ(t.comments.size(), comments.size() + 1);
    EXPECT_EQ(t.comments.front(), "three columns");
    for (std::size_t i = 0; i < comments.size(); ++i)
        EXPECT_EQ(t.comments[i + 1], "before row " + std::to_string(comments[i]));
}

// A bad value and a short row at places in either half of a block: each is named at its line, and of two the
// earlier in the file, as the line reader named them.
TEST(TableBlocks, TheFirstBadLineInTheFileIsNamedAtItsLine) {
    for (std::size_t bad : {1u, 200000u, 380000u, 600000u, 899999u}) {
        std::string text = long_table();
        const std::string row = table_row(bad) + "\n";
        const std::size_t at = text.find("\n" + row) + 1;
        ASSERT_NE(at, 0u);
        std::string value = text;
        value.replace(at, row.size(), std::to_string(bad) + ".25, 1x 2\n");
        const std::string bad_value = "long.txt:" + std::to_string(table_line_of(bad)) + ": field 2 '1x': not a number";
        EXPECT_EQ(table_rejection(value), bad_value) << bad;
        std::string short_row = text;
        short_row.replace(at, row.size(), "1 2\n");
        EXPECT_EQ(table_rejection(short_row),
                  "long.txt:" + std::to_string(table_line_of(bad)) + ": expected 3 fields (as line 3), got 2")
            << bad;
        // A short row later in the file than the bad value (in another half or block): the value's line is named.
        if (bad + 150000 < kTableRows) {
            const std::string later = table_row(bad + 150000) + "\n";
            value.replace(value.find("\n" + later) + 1, later.size(), "1 2\n");
            EXPECT_EQ(table_rejection(value), bad_value) << bad;
        }
    }
}

// A last line without '\n' is a row like any other (a plain table's last line needs none).
TEST(TableBlocks, ALastLineWithoutANewlineIsARow) {
    std::string text = long_table();
    text.pop_back();
    const NumericTable t = parse_table(text);
    ASSERT_EQ(t.rows(), kTableRows);
    EXPECT_EQ(t.columns[0].back(), static_cast<double>(kTableRows - 1) + 0.25);
    EXPECT_EQ(t.row_lines.back(), table_line_of(kTableRows - 1));
}

}  // namespace
}  // namespace driftlab::host
