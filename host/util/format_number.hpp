// Number-to-text for files that are read back: shortest text that parses to the same double.
#pragma once

#include <string>

namespace driftlab::host {

/// Shortest decimal text that round-trips to exactly `value` (std::to_chars); "nan"/"inf" for non-finite.
std::string format_double(double value);

/// Appends format_double(value) to `out` without a temporary string.
void append_double(std::string& out, double value);

}  // namespace driftlab::host
