// The log reader on randomly damaged logs (deterministic seeds): every damage ends as a log whose rows keep the
// reader's guarantees or as a DataError naming a line of the text, never another exception; and damage to one
// byte of one row is either read as that row or named at that row (or the next, whose t_s it may no longer follow).
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
#include "host/util/error.hpp"

namespace driftlab::host {
namespace {

constexpr std::size_t kRows = 30;

// A log with metadata, a gap line, a raw column and saturation flags: each part of the format the reader checks.
std::string clean_log() {
    std::string text = "# driftlab-log: 1\n# source: hil\n# sample_period_s: 0.5\n# adc_bits: 10\n# window: 8\n"
                       "t_s,seq,gyro,accel_x,accel_y,accel_z,raw_gyro,sat_flags\n";
    for (std::size_t k = 0; k < kRows; ++k) {
        if (k == 12) text += "# gap: link lost 1.0 s\n";
        text += std::to_string(0.5 * static_cast<double>(k) + 0.25) + "," + std::to_string(2 * k) + "," +
                std::to_string(511.25 + static_cast<double>(k % 7)) + ",470.5,474.125,622," + std::to_string(500 + k % 9) +
                "," + (k == 20 ? "1" : "0") + "\n";
    }
    return text;
}

std::size_t line_count(const std::string& text) {
    std::size_t lines = 0;
    for (char c : text) lines += c == '\n';
    return lines + (!text.empty() && text.back() != '\n');
}

struct Outcome {
    bool read = false;
    LogData log;
    std::string error;
    std::uint64_t error_line = 0;  // 0: the message names no line
};

Outcome read(const std::string& text) {
    Outcome out;
    std::istringstream in(text);
    try {
        out.log = parse_log(in, "mem.csv");
        out.read = true;
    } catch (const DataError& e) {
        out.error = e.what();
        const std::string prefix = "mem.csv:";
        EXPECT_EQ(out.error.rfind(prefix, 0), 0u) << out.error;
        std::size_t digits = prefix.size();
        while (digits < out.error.size() && std::isdigit(static_cast<unsigned char>(out.error[digits]))) ++digits;
        if (digits > prefix.size()) out.error_line = std::stoull(out.error.substr(prefix.size(), digits - prefix.size()));
    }
    // Any other exception escapes and fails the test: the command would have died without naming the place.
    return out;
}

void expect_reader_guarantees(const LogData& log, const std::string& text) {
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

const char* const kInsertions[] = {",", "\n", "nan", "-", "1e308", "#", " ", "\r", "inf", "0", "999999", "\"", "\t", "."};

TEST(LogReaderFuzz, DamageAnywhereIsReadWithItsGuaranteesOrNamedAtALineOfTheText) {
    const std::string clean = clean_log();
    std::mt19937 rng(20261203);
    std::size_t read_count = 0, refused = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        std::string text = clean;
        const int edits = 1 + static_cast<int>(rng() % 6);
        for (int e = 0; e < edits && !text.empty(); ++e) {
            // Half the edits land in the first 300 bytes: the magic line, the metadata and the header.
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
        const Outcome out = read(text);
        if (out.read) {
            ++read_count;
            expect_reader_guarantees(out.log, text);
        } else {
            ++refused;
            EXPECT_LE(out.error_line, line_count(text) + 1) << out.error;
        }
    }
    // Both outcomes occur, or the damage above was too mild or too harsh to test anything.
    EXPECT_GT(read_count, 30u);
    EXPECT_GT(refused, 1000u);
}

TEST(LogReaderFuzz, OneDamagedByteInARowIsReadAsThatRowOrNamedThere) {
    const std::string clean = clean_log();
    std::vector<std::size_t> row_starts;  // byte offset of each data row, with its line number
    std::vector<std::uint64_t> row_lines;
    std::uint64_t line = 1;
    bool header_seen = false;
    for (std::size_t i = 0; i < clean.size(); ++line) {
        const std::size_t end = clean.find('\n', i);
        if (header_seen && clean[i] != '#') {
            row_starts.push_back(i);
            row_lines.push_back(line);
        }
        if (clean.compare(i, 4, "t_s,") == 0) header_seen = true;
        i = end + 1;
    }
    ASSERT_EQ(row_starts.size(), kRows);

    std::mt19937 rng(7);
    std::size_t named = 0, kept = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const std::size_t r = rng() % kRows;
        const std::size_t start = row_starts[r];
        const std::size_t length = clean.find('\n', start) - start;
        std::string text = clean;
        char byte;
        do byte = static_cast<char>(rng() % 256);
        while (byte == '\n');  // a new line would renumber the rest: the test above covers it
        text[start + rng() % length] = byte;
        const Outcome out = read(text);
        if (out.read) {
            ++kept;
            // A row turned into a comment is a comment by the format; any other row is still there.
            const std::size_t expected = text[start] == '#' ? kRows - 1 : kRows;
            EXPECT_EQ(out.log.size(), expected) << text.substr(start, length);
            expect_reader_guarantees(out.log, text);
        } else {
            ++named;
            EXPECT_TRUE(out.error_line == row_lines[r] || out.error_line == row_lines[r] + 1)
                << "damaged line " << row_lines[r] << ": " << out.error;
        }
    }
    EXPECT_GT(named, 500u);
    EXPECT_GT(kept, 40u);
}

}  // namespace
}  // namespace driftlab::host
