// The report's "Recording" table: what a canonical log says of how it was made (its metadata header,
// docs/log-format.md §2) and what its rows hold, so that a page compared against a datasheet says which board or
// simulation, firmware, rate and smoothing the numbers below come from (docs/analysis.md §6).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "host/fit/file_analysis.hpp"

namespace driftlab::host::view {

/// The table's rows, (label, text), in the order shown: only those the log's metadata or rows give. Every log gives
/// its format, sample count, duration, output rate (from `sample_period_s`, else the rows' mean spacing) and channels;
/// source, board, simulator, firmware, start, smoothing and converter come from the metadata keys of the same names.
std::vector<std::pair<std::string, std::string>> recording_rows(const fit::LogOverview& log);

/// The rows as an HTML table under a heading.
std::string recording_section(const fit::LogOverview& log);

}  // namespace driftlab::host::view
