// The live status line of `driftlab record` on a terminal: elapsed time, rows, loss and the newest values in
// physical units (host/util/units.hpp), or how long the port has been away. docs/recording.md "Status line".
#pragma once

#include <optional>
#include <string>

#include "host/io/log_assembler.hpp"

namespace driftlab::host::io {

/// While the port is away: since when, and the recorder's next attempt to reopen it (host clock).
struct LinkLoss {
    double lost_for_s = 0.0;         ///< [s] since the port was lost
    int next_attempt = 1;            ///< number of the next reopen attempt (1 = the first)
    double next_attempt_in_s = 0.0;  ///< [s] until it
};

/// One line without newline, e.g.
/// "  12.3 s  rows 123  lost 0 (0.00 %)  gyro -1.23 deg/s  accel 470.0 474.0 622.0 counts  dropped 0", or while
/// the port is away (`lost`) "  12.3 s  rows 123  lost 0 (0.00 %)  PORT LOST 3.2 s ago, reconnect attempt 4 in 1.8 s".
std::string format_status_line(const AssemblyStats& stats, double wall_s, const std::optional<LinkLoss>& lost);

/// Lost frames as a percentage of frames sent (received - duplicates + lost); 0 when nothing was sent.
double loss_percent(const AssemblyStats& stats);

/// The SAMPLEs not written as rows, for a summary: "" when none, else e.g.
/// "skipped 3 samples: 2 repeated (time not after the previous row), 1 beyond the converter's reach".
std::string skipped_samples(const AssemblyStats& stats);

}  // namespace driftlab::host::io
