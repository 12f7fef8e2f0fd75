// The live status line of `driftlab record` on a terminal: elapsed time, rows, loss and the newest values in
// physical units (host/util/units.hpp). docs/recording.md "Status line".
#pragma once

#include <string>

#include "host/io/log_assembler.hpp"

namespace driftlab::host::io {

/// One line without newline, e.g.
/// "  12.3 s  rows 123  lost 0 (0.00 %)  gyro -1.23 deg/s  accel -0.82 0.75 1.00 g  dropped 0".
std::string format_status_line(const AssemblyStats& stats, double wall_s, bool connected);

/// Lost frames as a percentage of frames sent (received - duplicates + lost); 0 when nothing was sent.
double loss_percent(const AssemblyStats& stats);

/// The SAMPLEs not written as rows, for a summary: "" when none, else e.g.
/// "skipped 3 samples: 2 repeated (time not after the previous row), 1 beyond the converter's reach".
std::string skipped_samples(const AssemblyStats& stats);

}  // namespace driftlab::host::io
