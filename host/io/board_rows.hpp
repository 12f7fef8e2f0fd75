// A board's rows in the canonical log: the optional columns that `record`, `decode`, `hil` and the pseudo-terminal
// board's truth log write beside t_s, seq and the channels, and a receiver row as such a log row
// (docs/log-format.md §4).
#pragma once

#include <string>
#include <vector>

#include "driftlab/receiver/row_assembler.hpp"
#include "host/log/log_data.hpp"
#include "host/log/log_writer.hpp"

namespace driftlab::host::io {

/// flags column bit: the RAW frame belonging to this SAMPLE was lost.
inline constexpr int kFlagRawMissing = 1;

/// tick, sat_flags, n_window, dropped, temp_c (the die temperature [°C], kNoTemperatureC without a reading); then, in
/// raw mode, the raw codes and, with `flags`, the flags column (a log
/// that keeps a SAMPLE whose RAW was lost, receiver::MissingRaw::mark).
std::vector<std::string> board_columns(bool raw, bool flags);

/// `row` with board_columns(raw, flags)'s values: a lost RAW's codes are kLostRawCode and its flags
/// kFlagRawMissing.
LogRow board_log_row(const receiver::Row& row, bool raw, bool flags);

}  // namespace driftlab::host::io
