// Splitting a text line into fields without copying (the views point into the line).
#pragma once

#include <string_view>
#include <vector>

namespace driftlab::host {

/// Splits `line` at every `sep` into `out` (cleared first). "a,,b" gives three fields, "" gives one.
void split_fields(std::string_view line, char sep, std::vector<std::string_view>& out);

/// Splits at runs of spaces/tabs and at single commas (plain numeric tables); empty fields between
/// two commas are kept so a missing value is seen, leading/trailing blanks are not fields.
void split_numeric_fields(std::string_view line, std::vector<std::string_view>& out);

}  // namespace driftlab::host
