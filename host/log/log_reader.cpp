// Canonical log reader; see log_reader.hpp and docs/log-format.md.
#include "host/log/log_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "host/log/capture_file.hpp"
#include "host/log/line_blocks.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/input_file.hpp"
#include "host/util/parse_number.hpp"
#include "host/util/split_fields.hpp"

namespace driftlab::host {
namespace {

constexpr std::string_view kMagicKey = "driftlab-log";

/// Where each column of the file goes.
struct ColumnPlan {
    std::size_t field_count = 0;
    std::array<std::size_t, kRequiredLogColumns.size()> required_field{};  // field index of t_s, seq, channels
    std::vector<std::pair<std::size_t, std::vector<double>*>> optional_fields;
    std::vector<std::string> optional_names;  // same order
};

// The key and value of a magic line (text without its line end, not blank); none for another line.
std::optional<std::pair<std::string, std::string>> magic_key_value(std::string_view text) {
    auto kv = text.front() == '#' ? split_comment_key_value(text.substr(1)) : std::nullopt;
    if (!kv || kv->first != kMagicKey) return std::nullopt;
    return kv;
}

ColumnPlan plan_columns(const std::vector<std::string_view>& names, LogData& log, std::uint64_t line) {
    ColumnPlan plan;
    plan.field_count = names.size();
    std::vector<std::string> seen;
    for (const auto& raw : names) {
        const std::string name(trim_blanks(raw));
        if (name.empty()) throw DataError(log.source_name, line, "header has an empty column name");
        if (std::find(seen.begin(), seen.end(), name) != seen.end())
            throw DataError(log.source_name, line, "header names column '" + name + "' twice");
        seen.push_back(name);
    }
    for (std::size_t r = 0; r < kRequiredLogColumns.size(); ++r) {
        const auto it = std::find(seen.begin(), seen.end(), kRequiredLogColumns[r]);
        if (it == seen.end())
            throw DataError(log.source_name, line,
                            std::string("header lacks the required column '") + kRequiredLogColumns[r] +
                                "' (required: t_s,seq,gyro,accel_x,accel_y,accel_z)");
        plan.required_field[r] = static_cast<std::size_t>(it - seen.begin());
    }
    for (const char* name : kOptionalLogColumns) {
        const auto it = std::find(seen.begin(), seen.end(), name);
        if (it != seen.end()) {
            plan.optional_fields.emplace_back(static_cast<std::size_t>(it - seen.begin()), &log.optional_columns[name]);
            plan.optional_names.emplace_back(name);
        }
    }
    return plan;
}

/// A header names columns; rows start with a number. A line with a field "t_s" is a header wherever it is.
bool looks_like_header(std::string_view line, std::vector<std::string_view>& scratch) {
    split_fields(line, ',', scratch);
    for (const auto f : scratch)
        if (trim_blanks(f) == "t_s") return true;
    return parse_finite_double(scratch.front()).error == NumberError::not_a_number;
}

double parse_field(const LogData& log, std::uint64_t line, std::string_view field, std::size_t index,
                   std::string_view column) {
    const ParsedNumber p = parse_finite_double(field);
    if (p.error != NumberError::ok)
        throw DataError(log.source_name, line,
                        "field " + std::to_string(index + 1) + " (" + std::string(column) + ") '" +
                            std::string(trim_blanks(field)) + "': " + number_error_text(p.error));
    return p.value;
}

// Rows read but not yet appended to the log: one line's, or a block's (parse_log reads the rows of a long log in
// blocks, two at a time). The t_s order is checked as they are appended, in file order.
struct ParsedRows {
    std::vector<double> t_s;
    std::vector<std::uint64_t> seq, line;
    std::array<std::vector<double>, kChannelCount> counts;
    std::vector<double> optional;  // the optional columns' values, row after row
    std::vector<LogGap> gaps;      // before_row counted from the block's first row
    std::exception_ptr error;      // the block's first bad line: its rows before it are kept

    void clear() {
        t_s.clear();
        seq.clear();
        line.clear();
        for (auto& c : counts) c.clear();
        optional.clear();
        gaps.clear();
        error = nullptr;
    }
};

// The text of a `# gap: text` comment, from its key and value (split_comment_key_value()); none for another comment.
std::optional<std::string> gap_text(const std::optional<std::pair<std::string, std::string>>& kv) {
    if (kv && kv->first == "gap") return kv->second;
    return std::nullopt;
}

class Parser {
public:
    Parser(const std::string& name, const ReadOptions& options) : options_(options) { log_.source_name = name; }

    void line(std::string_view text, std::uint64_t number, bool terminated) {
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        if (trim_blanks(text).empty()) return;
        if (!seen_magic_) return magic(text, number);
        if (text.front() == '#') return comment(text.substr(1), number);
        if (!plan_) return header(text, number);
        try {
            row(text, number);
        } catch (const DataError& e) {
            if (terminated) throw;
            if (options_.drop_truncated_tail) {
                log_.dropped_cut_line = number;
                return;
            }
            std::string inner = e.what();
            const std::string prefix = log_.source_name + ":" + std::to_string(number) + ": ";
            if (inner.rfind(prefix, 0) == 0) inner.erase(0, prefix.size());
            refuse_truncated_tail(number, "): " + inner);
        }
        if (!terminated) {
            if (options_.drop_truncated_tail) {
                pop_last_row();
                log_.dropped_cut_line = number;
                return;
            }
            refuse_truncated_tail(number, ", so its last value may be cut)");
        }
    }

    /// The header is read: every line from here on is a row, a comment or blank.
    bool reading_rows() const { return plan_.has_value(); }

    /// The lines of `text` (each ending in '\n'), the first numbered `first_line`, into `out` (cleared first), up to
    /// the first bad one (kept in out.error). Writes `out` only: blocks are read on two threads at once.
    void read_block(std::string_view text, std::uint64_t first_line, ParsedRows& out) const {
        out.clear();
        std::vector<std::string_view> fields;
        try {
            for_each_line(text, first_line, [&](std::string_view line, std::uint64_t number) {
                if (trim_blanks(line).empty()) return;
                if (line.front() == '#') {
                    if (auto gap = gap_text(split_comment_key_value(line.substr(1))))
                        out.gaps.push_back({out.t_s.size(), number, *gap});
                    return;
                }
                read_row(line, number, fields, out);
            });
        } catch (...) {
            out.error = std::current_exception();
        }
    }

    /// The rows after the header, in blocks (line_blocks.hpp) appended in file order, so the first bad line in the
    /// file is the one named; a last line without '\n' goes through line(), which knows what a cut line means.
    /// `number` is the last line read so far, and becomes the file's last.
    void rows_in_blocks(std::istream& in, std::uint64_t& number) {
        std::array<ParsedRows, 2> halves;
        read_line_blocks(in, log_.source_name, number,
                         {[&](int half, std::string_view lines, std::uint64_t first) {
                              read_block(lines, first, halves[static_cast<std::size_t>(half)]);
                          },
                          [&](int half) { append(halves[static_cast<std::size_t>(half)]); },
                          [&](std::string_view text, std::uint64_t last) { line(text, last, false); }});
    }

    LogData finish(std::uint64_t lines) {
        if (lines == 0) throw DataError(log_.source_name, 0, "empty file (expected '# driftlab-log: 1')");
        if (!plan_)
            throw DataError(log_.source_name, lines,
                            "missing header: no 't_s,seq,gyro,accel_x,accel_y,accel_z' line before the end of file");
        if (log_.t_s.empty()) throw DataError(log_.source_name, lines, "log has a header but no data rows");
        // Grown row by row, a column holds room for up to twice its rows (524 288 at 360 000), and the analyses keep
        // the log for their whole run: 16 MB of gap's peak heap on an hour at 100 Hz.
        log_.t_s.shrink_to_fit();
        log_.seq.shrink_to_fit();
        for (auto& column : log_.counts) column.shrink_to_fit();
        for (auto& [name, column] : log_.optional_columns) column.shrink_to_fit();
        return std::move(log_);
    }

private:
    /// A last line without '\n': a writer killed mid-line. The recorder writes each frame to its capture before the
    /// log, so the recording's capture holds that row whole: say how to get it back.
    [[noreturn]] void refuse_truncated_tail(std::uint64_t number, const std::string& why) const {
        throw DataError(log_.source_name, number,
                        "truncated last line (no newline at the end of the file; the writer was probably "
                        "interrupted" +
                            why + "; --drop-cut-line reads the rest without it" + capture_remedy());
    }

    /// Where the capture is found: the file the metadata's `capture` key names (record writes its file name there,
    /// --capture or not) beside the log, else record's default name. One written to another folder is named as the
    /// metadata names it, for the user who put it there; with no capture known the remedy says nothing of one.
    std::string capture_remedy() const {
        const std::string named = log_.metadata.get("capture").value_or("");
        const std::filesystem::path folder = std::filesystem::path(log_.source_name).parent_path();
        std::vector<std::string> places;
        if (!named.empty()) places.push_back((folder / std::filesystem::path(named).filename()).string());
        const std::string by_default = default_capture_path(log_.source_name);
        if (places.empty() || places.front() != by_default) places.push_back(by_default);  // record's own name: once
        for (const std::string& capture : places) {
            std::ifstream file(capture, std::ios::binary);  // a capture by its magic line, not any file of that name
            if (file && starts_as_capture(file))
                return ", or rebuild the whole log from its capture: `driftlab decode " + capture + " -o LOG.csv`";
        }
        if (named.empty()) return "";
        return ", or rebuild the whole log with `driftlab decode CAPTURE -o LOG.csv` from its capture, which the "
               "metadata names '" +
               named + "' and is not beside the log";
    }

    void magic(std::string_view text, std::uint64_t number) {
        seen_magic_ = true;
        const auto kv = magic_key_value(text);
        if (!kv)
            throw DataError(log_.source_name, number,
                            "not a driftlab log: the first line must be '# driftlab-log: 1', got '" +
                                std::string(text.substr(0, 60)) + "'");
        if (kv->second != std::to_string(kLogFormatVersion))
            throw DataError(log_.source_name, number,
                            "log format version '" + kv->second + "' is not supported (this reader knows 1)");
    }

    void comment(std::string_view body, std::uint64_t number) {
        const auto kv = split_comment_key_value(body);
        if (auto gap = gap_text(kv)) {
            log_.gaps.push_back({log_.t_s.size(), number, std::move(*gap)});
            return;
        }
        if (plan_ || !kv) return;  // free comments, and key: value text among the rows, are notes only
        if (!LogMetadata::is_valid_key(kv->first))
            throw DataError(log_.source_name, number, "metadata key '" + kv->first + "' is not lower_snake_case");
        if (log_.metadata.has(kv->first))
            throw DataError(log_.source_name, number, "metadata key '" + kv->first + "' appears twice");
        if (!LogMetadata::is_valid_value(kv->second))
            throw DataError(log_.source_name, number, "metadata value of '" + kv->first + "' holds a carriage return");
        log_.metadata.set(kv->first, kv->second);
        log_.metadata.set_line(kv->first, number);
    }

    void header(std::string_view text, std::uint64_t number) {
        if (!looks_like_header(text, fields_))
            throw DataError(
                log_.source_name, number,
                "missing header: expected column names such as 't_s,seq,gyro,accel_x,accel_y,accel_z', got '" +
                    std::string(text.substr(0, 60)) + "'");
        split_fields(text, ',', fields_);
        plan_ = plan_columns(fields_, log_, number);
        header_line_ = number;
        // Converter resolution from the metadata: what the channel columns can hold (a wild value is a corrupt row).
        if (const auto bits = log_.metadata.get_int("adc_bits")) {
            range_ = converter_range(*bits);
        } else if (options_.assumed_adc_bits) {
            range_ = converter_range(*options_.assumed_adc_bits);
            range_assumed_ = true;
        }
    }

    void row(std::string_view text, std::uint64_t number) {
        one_.clear();
        read_row(text, number, fields_, one_);
        append(one_);
    }

    // One row's line into `out`: every check but the order of t_s, which append() makes.
    void read_row(std::string_view text, std::uint64_t number, std::vector<std::string_view>& fields,
                  ParsedRows& out) const {
        if (text.find("t_s") != std::string_view::npos && looks_like_header(text, fields))
            throw DataError(
                log_.source_name, number,
                "duplicate header (the first is on line " + std::to_string(header_line_) + "); two logs concatenated?");
        split_fields(text, ',', fields);
        if (fields.size() != plan_->field_count)
            throw DataError(log_.source_name, number,
                            "expected " + std::to_string(plan_->field_count) + " fields (as the header), got " +
                                std::to_string(fields.size()));
        const auto& req = plan_->required_field;
        const double t_s = parse_field(log_, number, fields[req[0]], req[0], "t_s");
        const auto seq = parse_unsigned(fields[req[1]]);
        if (!seq)
            throw DataError(log_.source_name, number,
                            "field " + std::to_string(req[1] + 1) + " (seq) '" +
                                std::string(trim_blanks(fields[req[1]])) + "': not a non-negative integer");
        std::array<double, kChannelCount> values{};
        for (std::size_t c = 0; c < kChannelCount; ++c) {
            values[c] = parse_field(log_, number, fields[req[2 + c]], req[2 + c], kRequiredLogColumns[2 + c]);
            if (range_ && !range_->holds_estimate(values[c]))
                throw DataError(
                    log_.source_name, number,
                    "field " + std::to_string(req[2 + c] + 1) + " (" + kRequiredLogColumns[2 + c] + ") '" +
                        std::string(trim_blanks(fields[req[2 + c]])) + "': beyond the " + std::to_string(range_->bits) +
                        "-bit converter's reach (" + format_double(range_->estimate_low()) + " to " +
                        format_double(range_->estimate_high()) + " counts" +
                        (range_assumed_
                             ? "; the metadata names no adc_bits, " + std::to_string(range_->bits) + " assumed"
                             : "") +
                        ")");
        }
        for (std::size_t i = 0; i < plan_->optional_fields.size(); ++i) {
            const std::size_t field = plan_->optional_fields[i].first;
            const std::string& name = plan_->optional_names[i];
            const double v = parse_field(log_, number, fields[field], field, name);
            out.optional.push_back(v);  // a row cut short by an error leaves values past its block's rows: never read
            // Four channel bits: anything else (1.5, -3) had been read bit by bit as if it were some set of them.
            if (name == "sat_flags" && !(v >= 0.0 && v <= 15.0 && v == std::floor(v)))
                throw DataError(log_.source_name, number,
                                "field " + std::to_string(field + 1) + " (sat_flags) '" +
                                    std::string(trim_blanks(fields[field])) +
                                    "': not a set of channel bits (an integer 0 to 15)");
            if (range_ && is_raw_code_column(name) && !range_->holds_raw_code(v))
                throw DataError(log_.source_name, number,
                                "field " + std::to_string(field + 1) + " (" + name + ") '" +
                                    std::string(trim_blanks(fields[field])) + "': not a code of the " +
                                    std::to_string(range_->bits) + "-bit converter (0 to " +
                                    format_double(range_->full) + ", or " + format_double(kLostRawCode) +
                                    " for a lost RAW frame)");
        }
        if (t_s < 0.0)
            throw DataError(log_.source_name, number,
                            "t_s " + format_double(t_s) +
                                " is before power-on (t_s counts from power-on, so it is never negative)");
        out.t_s.push_back(t_s);
        out.seq.push_back(*seq);
        out.line.push_back(number);
        for (std::size_t c = 0; c < kChannelCount; ++c) out.counts[c].push_back(values[c]);
    }

    // Appends `rows` after the log's last row, each after checking that t_s increases, then throws their block's error.
    void append(const ParsedRows& rows) {
        const std::size_t base = log_.t_s.size(), k = plan_->optional_fields.size();
        for (const LogGap& g : rows.gaps) log_.gaps.push_back({base + g.before_row, g.line, g.text});
        for (std::size_t r = 0; r < rows.t_s.size(); ++r) {
            const double t_s = rows.t_s[r];
            if (!log_.t_s.empty() && !(t_s > log_.t_s.back()))
                throw DataError(log_.source_name, rows.line[r],
                                "t_s " + format_double(t_s) + " is not after the previous row's " +
                                    format_double(log_.t_s.back()) + " (t_s must increase strictly)");
            log_.t_s.push_back(t_s);
            log_.seq.push_back(rows.seq[r]);
            for (std::size_t c = 0; c < kChannelCount; ++c) log_.counts[c].push_back(rows.counts[c][r]);
            for (std::size_t i = 0; i < k; ++i) plan_->optional_fields[i].second->push_back(rows.optional[r * k + i]);
        }
        if (rows.error) std::rethrow_exception(rows.error);
    }

    void pop_last_row() {
        log_.t_s.pop_back();
        log_.seq.pop_back();
        for (auto& c : log_.counts) c.pop_back();
        for (auto& [field, column] : plan_->optional_fields) column->pop_back();
    }

    ReadOptions options_;
    LogData log_;
    bool seen_magic_ = false;
    std::optional<ColumnPlan> plan_;
    std::uint64_t header_line_ = 0;
    std::optional<ConverterRange> range_;  // from the metadata's adc_bits, else ReadOptions::assumed_adc_bits
    bool range_assumed_ = false;
    std::vector<std::string_view> fields_;
    ParsedRows one_;  // row()'s one row
};

}  // namespace

LogData parse_log(std::istream& in, const std::string& source_name, const ReadOptions& options) {
    Parser parser(source_name, options);
    std::string text;
    std::uint64_t number = 0;
    bool ended = true;
    while (!parser.reading_rows() && read_line(in, text, source_name, number + 1, &ended)) {
        ++number;
        parser.line(text, number, ended);
    }
    if (parser.reading_rows()) parser.rows_in_blocks(in, number);
    if (in.bad()) throw DataError(source_name, number, "read error");
    return parser.finish(number);
}

LogData read_log(const std::string& path, const ReadOptions& options) {
    std::ifstream in = open_input_file(path);
    return parse_log(in, path, options);
}

std::string dropped_cut_line_note(const LogData& log) {
    if (log.dropped_cut_line == 0) return "";
    return log.source_name + ":" + std::to_string(log.dropped_cut_line) +
           ": the last line, cut without a newline, was left out (--drop-cut-line); its row is not analysed";
}

bool starts_as_log(std::istream& in) {
    std::uint64_t number = 0;
    std::string text;
    const auto next = [&]() {
        try {
            return read_line(in, text, "", ++number);
        } catch (const DataError&) {
            return false;  // a line too long for a log: not one; the table reader refuses it naming the file
        }
    };
    while (next()) {
        if (!text.empty() && text.back() == '\r') text.pop_back();
        if (trim_blanks(text).empty()) continue;  // the reader skips blank lines before the magic too
        // A damaged magic line ("# driftlab-log 1") is still a log, which the reader refuses saying why; read as a
        // plain table it had been fitted column by column, seq included.
        return magic_key_value(text).has_value() ||
               (trim_blanks(text).rfind('#', 0) == 0 && text.find("driftlab-log") != std::string::npos);
    }
    return false;
}

std::optional<std::pair<std::string, std::string>> split_comment_key_value(std::string_view body) {
    const auto colon = body.find(':');
    if (colon == std::string_view::npos) return std::nullopt;
    const std::string key(trim_blanks(body.substr(0, colon)));
    if (key.empty() || key.find(' ') != std::string::npos) return std::nullopt;
    return std::make_pair(key, std::string(trim_blanks(body.substr(colon + 1))));
}

}  // namespace driftlab::host
