// Stretches of a log by time: the rows a user keeps when a disturbance (a shock, the board picked up, a disturbed
// start) would otherwise be read as part of the sensor's behaviour.
#pragma once

#include <string>
#include <vector>

#include "host/log/log_data.hpp"

namespace driftlab::host {

/// The rows of `log` with from_s <= t_s <= to_s, every column and the gap events among them (their rows renumbered);
/// times stay since power-on. Throws DataError naming the log when no row lies in the window.
LogData rows_between(const LogData& log, double from_s, double to_s);

/// A stretch of time to leave out [s since power-on], both ends included.
struct TimeWindow {
    double from_s = 0.0;
    double to_s = 0.0;
    std::string by;  ///< what asked for it (an option name), carried into LogCut::by for messages
};

/// The rows of `log` outside every window, with a LogCut where each (overlapping ones merged) took rows out, so that
/// the join is not read as lost frames; gap events and earlier cuts between kept rows stay. Throws DataError naming
/// the log when a window holds no row (a window that misses is a mistaken time, not nothing to do) or no row is left.
LogData rows_outside(const LogData& log, std::vector<TimeWindow> windows);

/// The stretches of `log` whose rows flag one of `channels` saturated (`sat_flags`), each widened by `margin_s` on
/// either side: what a shock or a rail took, for rows_outside(). None when no row is flagged. Throws DataError naming
/// the log when it has no `sat_flags` column (a plain recording; `record` and `hil` write it).
std::vector<TimeWindow> saturated_stretches(const LogData& log, const std::array<bool, kChannelCount>& channels,
                                            double margin_s);

}  // namespace driftlab::host
