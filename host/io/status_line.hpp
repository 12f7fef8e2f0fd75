// The live status line of `driftlab record` on a terminal: elapsed time, rows, loss and the newest values in
// physical units (host/util/units.hpp), or how long the port has been away. docs/recording.md "Status line". Also
// the recorder's gap line and its summary's skipped samples: its other words for people.
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

/// The log's gap line (without "gap: ") for a link lost and regained, each figure naming its clock: the last row's
/// t_s is the board's, the time of the loss and its length the host's, e.g. "link lost after t_s=5.500 (board clock),
/// 3.990 s into the recording (host clock); reconnected after 11.759 s (host clock), 6 attempts". `last_t_s` is empty
/// when no row came before the loss.
std::string link_lost_gap(const std::optional<double>& last_t_s, double lost_at_s, double away_s, int attempts);

/// Lost frames as a percentage of frames sent (received - duplicates + lost); 0 when nothing was sent.
double loss_percent(const AssemblyStats& stats);

/// The SAMPLEs not written as rows, for a summary: "" when none, else e.g.
/// "skipped 3 samples: 2 repeated (time not after the previous row), 1 beyond the converter's reach".
std::string skipped_samples(const AssemblyStats& stats);

/// What arrived that the recording did not trust, for a summary: "" when nothing, else e.g. "untrusted frames: 1
/// shared its seq with another of other content (neither used; 1 row kept out), 1 VERSION and 0 CONFIG differing
/// from the handshake's ignored (each noted in the log)".
std::string untrusted_frames(const AssemblyStats& stats);

}  // namespace driftlab::host::io
