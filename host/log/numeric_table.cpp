// Plain numeric table reader; see numeric_table.hpp.
#include "host/log/numeric_table.hpp"

#include <fstream>
#include <string_view>

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

}  // namespace

NumericTable read_numeric_table(const std::string& path) {
    std::ifstream in = open_input_file(path);
    return parse_numeric_table(in, path);
}

NumericTable parse_numeric_table(std::istream& in, const std::string& path) {
    NumericTable table;
    table.source_name = path;
    std::string text;
    std::vector<std::string_view> fields;
    // The rows one after another, `width` values each: a vector per row had cost ten million one-value rows 560 MB.
    std::vector<double> flat;
    std::size_t width = 0;
    std::vector<std::uint64_t> line_numbers;
    std::uint64_t number = 0;
    bool any_line = false;
    while (read_line(in, text, path, number + 1)) {
        ++number;
        any_line = true;
        // A byte-order mark (editors on Windows write one) would make the first name unrecognisable.
        if (number == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
        std::string_view line = trim_blanks(text);
        if (line.empty()) continue;
        if (line.front() == '#') {
            table.comments.emplace_back(trim_blanks(line.substr(1)));
            continue;
        }
        split_numeric_fields(line, fields);
        if (line_numbers.empty() && table.names.empty() && is_name_line(fields)) {
            for (const auto f : fields) table.names.emplace_back(trim_blanks(f));
            continue;
        }
        for (std::size_t i = 0; i < fields.size(); ++i) {
            const ParsedNumber p = parse_finite_double(fields[i]);
            if (p.error != NumberError::ok) {
                // A semicolon-separated or decimal-comma table (a spreadsheet's export in many locales) fails here.
                const bool locale_export =
                    p.error == NumberError::not_a_number && fields[i].find_first_of(";") != std::string_view::npos;
                throw DataError(
                    path, number,
                    "field " + std::to_string(i + 1) + " '" + std::string(trim_blanks(fields[i])) +
                        "': " + number_error_text(p.error) +
                        (locale_export ? " (fields are separated by blanks, tabs or commas and use a decimal "
                                         "point: export the table with those, not semicolons and decimal "
                                         "commas)"
                                       : ""));
            }
            flat.push_back(p.value);
        }
        if (!line_numbers.empty() && fields.size() != width)
            throw DataError(path, number,
                            "expected " + std::to_string(width) + " fields (as line " +
                                std::to_string(line_numbers.front()) + "), got " + std::to_string(fields.size()));
        if (line_numbers.empty()) width = fields.size();
        // One name over one data line names a series written on one line; a second line shows whether it was one.
        if (!table.names.empty() && !(table.names.size() == 1 && line_numbers.empty())) {
            const bool first_unchecked = table.names.size() == 1 && line_numbers.size() == 1;
            const std::size_t got = width;
            if (got != table.names.size())
                throw DataError(path, first_unchecked ? line_numbers.front() : number,
                                "expected " + std::to_string(table.names.size()) + " fields (as the name line), got " +
                                    std::to_string(got));
        }
        line_numbers.push_back(number);
    }
    if (!any_line) throw DataError(path, 0, "empty file");
    if (line_numbers.empty()) throw DataError(path, number, "no numeric data lines");

    if (line_numbers.size() == 1 && table.names.size() <= 1) {
        table.row_lines.assign(flat.size(), line_numbers.front());
        table.columns.push_back(std::move(flat));
    } else if (width == 1) {
        table.row_lines = std::move(line_numbers);
        table.columns.push_back(std::move(flat));
    } else {
        table.row_lines = std::move(line_numbers);
        const std::size_t rows = table.row_lines.size();
        table.columns.assign(width, std::vector<double>(rows));
        for (std::size_t r = 0; r < rows; ++r)
            for (std::size_t c = 0; c < width; ++c) table.columns[c][r] = flat[r * width + c];
    }
    if (table.names.size() != table.columns.size()) {
        table.names.clear();
        for (std::size_t c = 0; c < table.columns.size(); ++c) table.names.push_back("col" + std::to_string(c + 1));
    }
    return table;
}

}  // namespace driftlab::host
