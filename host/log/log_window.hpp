// A stretch of a log by time: the rows a user keeps when a disturbance (a shock, the board picked up, a disturbed
// start) would otherwise be read as part of the sensor's behaviour.
#pragma once

#include "host/log/log_data.hpp"

namespace driftlab::host {

/// The rows of `log` with from_s <= t_s <= to_s, every column and the gap events among them (their rows renumbered);
/// times stay since power-on. Throws DataError naming the log when no row lies in the window.
LogData rows_between(const LogData& log, double from_s, double to_s);

}  // namespace driftlab::host
