// Plain numeric files: one or more columns separated by blanks or commas, `#` comment lines, an optional
// first line of column names. Used by `allan --kind` and for recordings that are not canonical logs.
// Spec: docs/log-format.md §8.
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace driftlab::host {

/// Columns of numbers with their names ("col1", "col2"... when the file has no name line).
struct NumericTable {
    std::string source_name;
    std::vector<std::string> names;
    std::vector<std::vector<double>> columns;
    std::vector<std::string> comments;     ///< text of the `#` lines, without the '#'
    std::vector<std::uint64_t> row_lines;  ///< the file line (1-based) of each row; all one line for a one-line series

    std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
    /// The file line of `row` for messages; 0 (no line) for a table not read from a file.
    std::uint64_t line_of_row(std::size_t row) const { return row < row_lines.size() ? row_lines[row] : 0; }
    /// Index of the column called `name`; throws UsageError listing the names when there is none.
    std::size_t column_index(const std::string& name) const;
};

/// Reads `path`. A file with exactly one data line is read as ONE column (a series written on one line,
/// like gyro2_x.txt); otherwise every data line must have the same number of fields. Throws DataError
/// (file, line) on a non-numeric, NaN or infinite value, a ragged row, an empty file.
NumericTable read_numeric_table(const std::string& path);

/// read_numeric_table() of a file already open (from its start); `path` names it in messages.
NumericTable parse_numeric_table(std::istream& in, const std::string& path);

}  // namespace driftlab::host
