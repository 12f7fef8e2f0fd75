// Plain numeric table reader; see numeric_table.hpp.
#include "host/log/numeric_table.hpp"

#include <array>
#include <exception>
#include <fstream>
#include <string_view>

#include "host/log/line_blocks.hpp"
#include "host/util/error.hpp"
#include "host/util/input_file.hpp"
#include "host/util/parse_number.hpp"
#include "host/util/split_fields.hpp"

namespace driftlab::host {

std::size_t NumericTable::column_index(const std::string& name) const {
    std::string known;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i] == name) return i;
        known += (i ? ", " : "") + names[i];
    }
    throw UsageError(source_name + ": no column '" + name + "' (columns: " + known + ")");
}

namespace {

bool is_name_line(const std::vector<std::string_view>& fields) {
    for (const auto f : fields) {
        const NumberError e = parse_finite_double(f).error;
        if (e == NumberError::not_a_number) {
            const std::string_view t = trim_blanks(f);
            // "nan"/"inf" spelled out are bad values, not names.
            if (t != "nan" && t != "NaN" && t != "inf" && t != "-inf") return true;
        }
    }
    return false;
}

// True for a blank line or a comment (its text, without the '#', kept in `comments`): neither is a row.
bool blank_or_comment(std::string_view trimmed, std::vector<std::string>& comments) {
    if (trimmed.empty()) return true;
    if (trimmed.front() != '#') return false;
    comments.emplace_back(trim_blanks(trimmed.substr(1)));
    return true;
}

// Values and line numbers of a table's data lines, and its comments: the whole table's as it is read, or one half
// of a block's (line_blocks.hpp), which keeps the first error it met.
struct TableRows {
    std::vector<double> flat;  // the rows one after another, `width` values each
    std::vector<std::uint64_t> lines;
    std::vector<std::string> comments;
    std::exception_ptr error;

    void clear() {
        flat.clear();
        lines.clear();
        comments.clear();
        error = nullptr;
    }
};

class TableReader {
public:
    explicit TableReader(const std::string& path) { table_.source_name = path; }

    /// A line of the file's head, read one at a time until its shape is settled().
    void line(std::string text, std::uint64_t number) {
        // A byte-order mark (editors on Windows write one) would make the first name unrecognisable.
        if (number == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
        const std::string_view line = trim_blanks(text);
        if (blank_or_comment(line, rows_.comments)) return;
        split_numeric_fields(line, fields_);
        if (rows_.lines.empty() && table_.names.empty() && is_name_line(fields_)) {
            for (const auto f : fields_) table_.names.emplace_back(trim_blanks(f));
            return;
        }
        parse_values(fields_, number, rows_.flat);
        const std::vector<std::uint64_t>& lines = rows_.lines;
        if (lines.empty())
            width_ = fields_.size();
        else
            check_width(fields_.size(), number);
        // One name over one data line names a series written on one line; a second line shows whether it was one.
        if (!table_.names.empty() && !(table_.names.size() == 1 && lines.empty())) {
            const bool first_unchecked = table_.names.size() == 1 && lines.size() == 1;
            if (width_ != table_.names.size())
                throw DataError(table_.source_name, first_unchecked ? lines.front() : number,
                                "expected " + std::to_string(table_.names.size()) + " fields (as the name line), got " +
                                    std::to_string(width_));
        }
        rows_.lines.push_back(number);
    }

    /// Two data lines are read: every later one must have their width, whatever names the head gave.
    bool settled() const { return rows_.lines.size() >= 2; }

    /// The lines of a block's half after the head into `out` (cleared first), up to the first bad one (kept in
    /// out.error). Writes `out` only: the halves are read at once.
    void read_rows(std::string_view lines, std::uint64_t first_line, TableRows& out) const {
        out.clear();
        std::vector<std::string_view> fields;
        try {
            for_each_line(lines, first_line, [&](std::string_view text, std::uint64_t number) {
                const std::string_view line = trim_blanks(text);
                if (blank_or_comment(line, out.comments)) return;
                split_numeric_fields(line, fields);
                parse_values(fields, number, out.flat);
                check_width(fields.size(), number);
                out.lines.push_back(number);
            });
        } catch (...) {
            out.error = std::current_exception();
        }
    }

    /// Adds a half's rows and comments after those read, then throws its error.
    void append(const TableRows& half) {
        // A row cut short by its error left values past the half's rows: they are not the table's.
        rows_.flat.insert(rows_.flat.end(), half.flat.begin(),
                          half.flat.begin() + static_cast<std::ptrdiff_t>(half.lines.size() * width_));
        rows_.lines.insert(rows_.lines.end(), half.lines.begin(), half.lines.end());
        rows_.comments.insert(rows_.comments.end(), half.comments.begin(), half.comments.end());
        if (half.error) std::rethrow_exception(half.error);
    }

    NumericTable finish(std::uint64_t lines_read) {
        if (lines_read == 0) throw DataError(table_.source_name, 0, "empty file");
        if (rows_.lines.empty()) throw DataError(table_.source_name, lines_read, "no numeric data lines");
        table_.comments = std::move(rows_.comments);
        if (rows_.lines.size() == 1 && table_.names.size() <= 1) {
            table_.row_lines.assign(rows_.flat.size(), rows_.lines.front());
            table_.columns.push_back(std::move(rows_.flat));
        } else if (width_ == 1) {
            table_.row_lines = std::move(rows_.lines);
            table_.columns.push_back(std::move(rows_.flat));
        } else {
            table_.row_lines = std::move(rows_.lines);
            const std::size_t rows = table_.row_lines.size();
            table_.columns.assign(width_, std::vector<double>(rows));
            for (std::size_t r = 0; r < rows; ++r)
                for (std::size_t c = 0; c < width_; ++c) table_.columns[c][r] = rows_.flat[r * width_ + c];
        }
        if (table_.names.size() != table_.columns.size()) {
            table_.names.clear();
            for (std::size_t c = 0; c < table_.columns.size(); ++c)
                table_.names.push_back("col" + std::to_string(c + 1));
        }
        return std::move(table_);
    }

private:
    void parse_values(const std::vector<std::string_view>& fields, std::uint64_t number,
                      std::vector<double>& out) const {
        for (std::size_t i = 0; i < fields.size(); ++i) {
            const ParsedNumber p = parse_finite_double(fields[i]);
            if (p.error == NumberError::ok) {
                out.push_back(p.value);
                continue;
            }
            // A semicolon-separated or decimal-comma table (a spreadsheet's export in many locales) fails here.
            const bool locale_export =
                p.error == NumberError::not_a_number && fields[i].find_first_of(";") != std::string_view::npos;
            throw DataError(table_.source_name, number,
                            "field " + std::to_string(i + 1) + " '" + std::string(trim_blanks(fields[i])) +
                                "': " + number_error_text(p.error) +
                                (locale_export ? " (fields are separated by blanks, tabs or commas and use a decimal "
                                                 "point: export the table with those, not semicolons and decimal "
                                                 "commas)"
                                               : ""));
        }
    }

    void check_width(std::size_t got, std::uint64_t number) const {
        if (got != width_)
            throw DataError(table_.source_name, number,
                            "expected " + std::to_string(width_) + " fields (as line " +
                                std::to_string(rows_.lines.front()) + "), got " + std::to_string(got));
    }

    NumericTable table_;
    TableRows rows_;  // the table's rows and comments as they are read
    std::size_t width_ = 0;
    std::vector<std::string_view> fields_;
};

}  // namespace

NumericTable read_numeric_table(const std::string& path) {
    std::ifstream in = open_input_file(path);
    return parse_numeric_table(in, path);
}

NumericTable parse_numeric_table(std::istream& in, const std::string& path) {
    TableReader reader(path);
    std::string text;
    std::uint64_t number = 0;
    while (!reader.settled() && read_line(in, text, path, number + 1)) reader.line(std::move(text), ++number);
    if (reader.settled()) {
        // A ten-million-line series is parsed on both cores, its first bad line still named (line_blocks.hpp).
        std::array<TableRows, 2> halves;
        read_line_blocks(in, path, number,
                         {[&](int half, std::string_view lines, std::uint64_t first) {
                              reader.read_rows(lines, first, halves[static_cast<std::size_t>(half)]);
                          },
                          [&](int half) { reader.append(halves[static_cast<std::size_t>(half)]); },
                          [&](std::string_view last, std::uint64_t n) { reader.line(std::string(last), n); }});
    }
    if (in.bad()) throw DataError(path, number, "read error");
    return reader.finish(number);
}

}  // namespace driftlab::host
