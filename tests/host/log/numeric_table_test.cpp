// Plain numeric tables and the real recordings in the shared folder (docs/log-format.md §6).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "host/log/log_reader.hpp"
#include "host/log/numeric_table.hpp"
#include "host/util/error.hpp"
#include "host/util/input_file.hpp"
#include "tests/support/data_error.hpp"
#include "tests/support/temp_dir.hpp"

namespace driftlab::host {
namespace {

std::string rejection(const std::string& name, const std::string& text) {
    const std::string path = test_support::write_temp_file(name, text);
    return test_support::data_error_of([&] { read_numeric_table(path); }, text);
}

TEST(NumericTable, ColumnsSplitByBlanksOrCommasWithNamesAndComments) {
    const auto t =
        read_numeric_table(test_support::write_temp_file("a.txt", "# comment\nt, x  y\n0, 1 2\n1,3,4\n\n2\t5 6\n"));
    ASSERT_EQ(t.columns.size(), 3u);
    EXPECT_EQ(t.names, (std::vector<std::string>{"t", "x", "y"}));
    EXPECT_EQ(t.columns[2], (std::vector<double>{2, 4, 6}));
    EXPECT_EQ(t.column_index("x"), 1u);
    // Each row's file line, for messages: comments, the name line and a blank line come between.
    EXPECT_EQ(t.row_lines, (std::vector<std::uint64_t>{3, 4, 6}));
    EXPECT_EQ(t.line_of_row(2), 6u);
    EXPECT_EQ(t.line_of_row(3), 0u);
    EXPECT_THROW(t.column_index("z"), UsageError);
    ASSERT_EQ(t.comments.size(), 1u);
}

TEST(NumericTable, OneLineFileIsOneSeries) {
    const auto t = read_numeric_table(test_support::write_temp_file("b.txt", "1.5 2.5 3.5 4.5"));
    ASSERT_EQ(t.columns.size(), 1u);
    EXPECT_EQ(t.columns[0], (std::vector<double>{1.5, 2.5, 3.5, 4.5}));
    EXPECT_EQ(t.names[0], "col1");
    // With a name: the one line is still one named series.
    const auto named = read_numeric_table(test_support::write_temp_file("o.txt", "gx\n1 2 3 4 5 6\n"));
    ASSERT_EQ(named.columns.size(), 1u);
    EXPECT_EQ(named.names[0], "gx");
    EXPECT_EQ(named.rows(), 6u);
    EXPECT_EQ(named.line_of_row(5), 2u);  // a one-line series: every value on that line
}

// A byte-order mark before the name line is not part of the first name: the time column is still found by name.
TEST(NumericTable, AByteOrderMarkIsNotPartOfTheFirstName) {
    const auto t = read_numeric_table(test_support::write_temp_file("bom.csv", "\xEF\xBB\xBFt_s,gx\n0,1\n0.01,2\n"));
    EXPECT_EQ(t.names, (std::vector<std::string>{"t_s", "gx"}));
    EXPECT_EQ(t.columns[0], (std::vector<double>{0.0, 0.01}));
}

TEST(NumericTable, RejectionsNameTheLine) {
    EXPECT_NE(rejection("e.txt", "").find("empty file"), std::string::npos);
    EXPECT_NE(rejection("c.txt", "# only\n").find("no numeric data lines"), std::string::npos);
    EXPECT_NE(rejection("r.txt", "1 2\n3 4\n5\n").find(":3: expected 2 fields (as line 1), got 1"), std::string::npos);
    EXPECT_NE(rejection("n.txt", "1 2\n3 nan\n").find(":2: field 2 'nan': not finite"), std::string::npos);
    EXPECT_NE(rejection("m.txt", "1,2\n3,,4\n").find(":2: field 2 '': empty field"), std::string::npos);
    // One name over lines of several fields: the first data line is named, as with several names.
    EXPECT_NE(rejection("w.txt", "gx\n1 2\n3 4\n").find(":2: expected 1 fields (as the name line), got 2"),
              std::string::npos);
    EXPECT_NE(rejection("x.txt", "a b\n1 2 3\n").find(":2: expected 2 fields (as the name line), got 3"),
              std::string::npos);
    // A spreadsheet's export with semicolons and decimal commas is told what the reader expects.
    const std::string semicolons = rejection("s.txt", "t;gx\n0;0,5\n0,01;0,6\n");
    EXPECT_NE(semicolons.find(":2: field 1 '0;0': not a number (fields are separated by blanks, tabs or commas"),
              std::string::npos)
        << semicolons;
    EXPECT_EQ(rejection("a.txt", "1 2\n3 abc\n").find("semicolons"), std::string::npos);  // not said of other words
}

TEST(NumericTable, ReadsTheRealRecordings) {
    const std::filesystem::path dir = std::filesystem::path(DRIFTLAB_SHARED_DIR) / "data" / "real";
    const auto gyro = dir / "gyro2_x.txt";
    const auto mpu = dir / "mpu6050_unmoved-with-x-pointing-forward-10min.csv";
    if (!std::filesystem::exists(gyro) || !std::filesystem::exists(mpu))
        GTEST_SKIP() << "real recordings not found in " << dir << " (shared data folder absent)";
    const auto g = read_numeric_table(gyro.string());
    ASSERT_EQ(g.columns.size(), 1u);
    EXPECT_EQ(g.rows(), 238256u);  // PROVENANCE.md
    EXPECT_DOUBLE_EQ(g.columns[0][0], 1.2425);
    const auto m = read_numeric_table(mpu.string());
    EXPECT_EQ(m.names.size(), 8u);
    EXPECT_EQ(m.names[0], "t_s");
    EXPECT_EQ(m.rows(), 65067u);
    EXPECT_DOUBLE_EQ(m.columns[m.column_index("temp_C")][0], 25.51824);
}

}  // namespace
}  // namespace driftlab::host

// Readers of untrusted files are bounded (docs/security.md): a line past kMaxLineBytes is refused naming its line,
// in a table and in a log alike, and one just under it is read.
TEST(NumericTable, ALineLongerThanTheLimitIsRefusedNamingIt) {
    using driftlab::host::kMaxLineBytes;
    std::string values;
    while (values.size() < kMaxLineBytes - 16) values += "1.25 ";
    std::istringstream under(values + "\n");
    EXPECT_NO_THROW(driftlab::host::parse_numeric_table(under, "under.txt"));
    std::istringstream over("# a comment\n" + values + values + "\n");
    try {
        driftlab::host::parse_numeric_table(over, "over.txt");
        FAIL() << "a line past the limit was read";
    } catch (const driftlab::host::DataError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("over.txt:2: a line longer than 16777216 bytes", 0), 0u) << e.what();
    }
    std::istringstream log("# driftlab-log: 1\n" + values + values + "\n");
    try {
        driftlab::host::parse_log(log, "over.csv");
        FAIL() << "a log line past the limit was read";
    } catch (const driftlab::host::DataError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("over.csv:2: a line longer than", 0), 0u) << e.what();
    }
}
