// The log reader and the plain-table reader on randomly damaged files (deterministic seeds): every damage ends as
// data that keeps the reader's guarantees or as a DataError naming a line of the text, never another exception; and
// damage to one byte of one row is either read as that row or named at that row (a log's also at the next, whose t_s
// it may no longer precede).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "host/log/log_reader.hpp"
#include "host/log/numeric_table.hpp"
#include "host/util/error.hpp"

namespace driftlab::host {
namespace {

constexpr std::size_t kRows = 30;

// A log with metadata, a gap line, a raw column and saturation flags: each part of the format the reader checks.
std::string clean_log() {
    std::string text =
        "# driftlab-log: 1\n# source: hil\n# sample_period_s: 0.5\n# adc_bits: 10\n# window: 8\n"
        "t_s,seq,gyro,accel_x,accel_y,accel_z,raw_gyro,sat_flags\n";
    for (std::size_t k = 0; k < kRows; ++k) {
        if (k == 12) text += "# gap: link lost 1.0 s\n";
        text += std::to_string(0.5 * static_cast<double>(k) + 0.25) + "," + std::to_string(2 * k) + "," +
                std::to_string(511.25 + static_cast<double>(k % 7)) + ",470.5,474.125,622," +
                std::to_string(500 + k % 9) + "," + (k == 20 ? "1" : "0") + "\n";
    }
    return text;
}

std::size_t line_count(const std::string& text) {
    std::size_t lines = 0;
    for (char c : text) lines += c == '\n';
    return lines + (!text.empty() && text.back() != '\n');
}

/// The line a DataError's message names ("mem.csv:12: ..."), 0 when it names none; fails the test if the message
/// does not start with the file's name.
std::uint64_t named_line(const std::string& message) {
    const std::string prefix = "mem.csv:";
    EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
    std::size_t digits = prefix.size();
    while (digits < message.size() && std::isdigit(static_cast<unsigned char>(message[digits]))) ++digits;
    return digits > prefix.size() ? std::stoull(message.substr(prefix.size(), digits - prefix.size())) : 0;
}

/// What a reader made of a text: its data, or the line its DataError named. Any other exception escapes read_text()
/// and fails the test: the command would have died without naming the place.
template <typename Data>
struct Outcome {
    bool read = false;
    Data data;
    std::string error;
    std::uint64_t error_line = 0;
};

void expect_log_guarantees(const LogData& log, const std::string& text) {
    ASSERT_GT(log.size(), 0u) << text;
    EXPECT_EQ(log.seq.size(), log.size());
    for (const auto& column : log.counts) {
        ASSERT_EQ(column.size(), log.size());
        for (double v : column) EXPECT_TRUE(std::isfinite(v)) << text;
    }
    for (const auto& [name, column] : log.optional_columns) EXPECT_EQ(column.size(), log.size()) << name;
    for (std::size_t i = 1; i < log.size(); ++i) EXPECT_GT(log.t_s[i], log.t_s[i - 1]) << text;
    EXPECT_GE(log.t_s.front(), 0.0);
}

// A logger's export: a comment, a name line, blanks and commas mixed.
std::string clean_table() {
    std::string text = "# exported by a logger\nt_s, gx, ax\n";
    for (std::size_t k = 0; k < kRows; ++k)
        text += std::to_string(0.01 * static_cast<double>(k)) + ", " +
                std::to_string(0.125 * static_cast<double>(k % 5)) + "  " +
                std::to_string(-0.0012 + 1e-4 * static_cast<double>(k % 3)) + "\n";
    return text;
}

void expect_table_guarantees(const NumericTable& table, const std::string& text) {
    ASSERT_FALSE(table.columns.empty()) << text;
    ASSERT_GT(table.rows(), 0u) << text;
    if (!table.names.empty()) {
        EXPECT_EQ(table.names.size(), table.columns.size()) << text;
    }
    EXPECT_EQ(table.row_lines.size(), table.rows());
    for (const auto& column : table.columns) {
        ASSERT_EQ(column.size(), table.rows());
        for (double v : column) EXPECT_TRUE(std::isfinite(v)) << text;
    }
    for (std::size_t i = 1; i < table.row_lines.size(); ++i) EXPECT_LE(table.row_lines[i - 1], table.row_lines[i]);
    EXPECT_LE(table.row_lines.back(), line_count(text));
}

/// `clean` after one to six random edits: bytes replaced, spans cut or copied, tokens a reader must weigh inserted,
/// the text cut short. Half of them land in the first 300 bytes, where the magic line, metadata and header are.
std::string damaged(const std::string& clean, std::mt19937& rng) {
    static const char* const kInsertions[] = {",",  "\n",  "nan", "-",      "1e308", "#",  " ",
                                              "\r", "inf", "0",   "999999", "\"",    "\t", "."};
    std::string text = clean;
    const int edits = 1 + static_cast<int>(rng() % 6);
    for (int e = 0; e < edits && !text.empty(); ++e) {
        const std::size_t span = rng() % 2 ? std::min<std::size_t>(300, text.size()) : text.size();
        const std::size_t at = rng() % span;
        switch (rng() % 5) {
        case 0: text[at] = static_cast<char>(rng() % 256); break;
        case 1: text.erase(at, 1 + rng() % 50); break;
        case 2: text.insert(at, kInsertions[rng() % std::size(kInsertions)]); break;
        case 3: text.resize(at); break;
        default: {
            const std::size_t from = rng() % text.size();
            text.insert(at, text.substr(from, 1 + rng() % 200));
        }
        }
    }
    return text;
}

/// Byte offset and line number of each data line of `clean`: lines after the one starting with `header` that are not
/// comments.
struct RowPlaces {
    std::vector<std::size_t> starts;
    std::vector<std::uint64_t> lines;
};

RowPlaces row_places(const std::string& clean, const std::string& header) {
    RowPlaces rows;
    std::uint64_t line = 1;
    bool header_seen = false;
    for (std::size_t i = 0; i < clean.size(); ++line) {
        if (header_seen && clean[i] != '#') {
            rows.starts.push_back(i);
            rows.lines.push_back(line);
        }
        if (clean.compare(i, header.size(), header) == 0) header_seen = true;
        i = clean.find('\n', i) + 1;
    }
    return rows;
}

/// `clean` with one byte of data line `start` (of `length` bytes) replaced by any byte but a new line (which would
/// renumber the rest: damaged() covers it).
std::string one_byte_damaged(const std::string& clean, std::size_t start, std::size_t length, std::mt19937& rng) {
    std::string text = clean;
    char byte;
    do byte = static_cast<char>(rng() % 256);
    while (byte == '\n');
    text[start + rng() % length] = byte;
    return text;
}

// The canonical log: a damaged row's t_s may be refused at the next row, which no longer follows it.
struct LogFormat {
    using Data = LogData;
    static constexpr std::uint64_t kNextRowMayBeNamed = 1;
    static std::string clean() { return clean_log(); }
    static Data parse(std::istream& in) { return parse_log(in, "mem.csv"); }
    static std::size_t rows(const Data& log) { return log.size(); }
    static void expect_guarantees(const Data& log, const std::string& text) { expect_log_guarantees(log, text); }
};

// A plain table: a damaged row is refused at its own line.
struct TableFormat {
    using Data = NumericTable;
    static constexpr std::uint64_t kNextRowMayBeNamed = 0;
    static std::string clean() { return clean_table(); }
    static Data parse(std::istream& in) { return parse_numeric_table(in, "mem.csv"); }
    static std::size_t rows(const Data& table) { return table.rows(); }
    static void expect_guarantees(const Data& table, const std::string& text) { expect_table_guarantees(table, text); }
};

template <typename Format>
Outcome<typename Format::Data> read_text(const std::string& text) {
    Outcome<typename Format::Data> out;
    std::istringstream in(text);
    try {
        out.data = Format::parse(in);
        out.read = true;
    } catch (const DataError& e) {
        out.error = e.what();
        out.error_line = named_line(out.error);
    }
    return out;
}

template <typename Format>
void expect_damage_anywhere_read_or_named(std::uint32_t seed) {
    const std::string clean = Format::clean();
    std::mt19937 rng(seed);
    std::size_t read_count = 0, refused = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const std::string text = damaged(clean, rng);
        const auto out = read_text<Format>(text);
        if (out.read) {
            ++read_count;
            Format::expect_guarantees(out.data, text);
        } else {
            ++refused;
            EXPECT_LE(out.error_line, line_count(text) + 1) << out.error;
        }
    }
    // Both outcomes occur, or the damage above was too mild or too harsh to test anything.
    EXPECT_GT(read_count, 30u);
    EXPECT_GT(refused, 1000u);
}

template <typename Format>
void expect_a_damaged_row_read_or_named_there(std::uint32_t seed) {
    const std::string clean = Format::clean();
    const RowPlaces rows = row_places(clean, "t_s,");
    ASSERT_EQ(rows.starts.size(), kRows);
    std::mt19937 rng(seed);
    std::size_t named = 0, kept = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const std::size_t r = rng() % kRows;
        const std::size_t start = rows.starts[r];
        const std::size_t length = clean.find('\n', start) - start;
        const std::string text = one_byte_damaged(clean, start, length, rng);
        const auto out = read_text<Format>(text);
        if (out.read) {
            ++kept;
            // A row turned into a comment is a comment by the format; any other row is still there.
            const std::size_t expected = text[start] == '#' ? kRows - 1 : kRows;
            EXPECT_EQ(Format::rows(out.data), expected) << text.substr(start, length);
            Format::expect_guarantees(out.data, text);
        } else {
            ++named;
            EXPECT_GE(out.error_line, rows.lines[r]) << out.error;
            EXPECT_LE(out.error_line, rows.lines[r] + Format::kNextRowMayBeNamed) << out.error;
        }
    }
    EXPECT_GT(named, 500u);
    EXPECT_GT(kept, 40u);
}

TEST(LogReaderFuzz, DamageAnywhereIsReadWithItsGuaranteesOrNamedAtALineOfTheText) {
    expect_damage_anywhere_read_or_named<LogFormat>(20261203);
}

TEST(LogReaderFuzz, OneDamagedByteInARowIsReadAsThatRowOrNamedThere) {
    expect_a_damaged_row_read_or_named_there<LogFormat>(7);
}

TEST(TableReaderFuzz, DamageAnywhereIsReadWithItsGuaranteesOrNamedAtALineOfTheText) {
    expect_damage_anywhere_read_or_named<TableFormat>(31);
}

TEST(TableReaderFuzz, OneDamagedByteInARowIsReadAsThatRowOrNamedThere) {
    expect_a_damaged_row_read_or_named_there<TableFormat>(11);
}

}  // namespace
}  // namespace driftlab::host
