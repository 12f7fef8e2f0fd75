// Whether a log's outputs were compensated on board: the `cal_state` and `cal_id` its metadata took from the board's
// VERSION (docs/log-format.md §2). The analyses read it so that the host never compensates twice.
#pragma once

#include <optional>
#include <string>

#include "host/log/log_metadata.hpp"

namespace driftlab::host {

/// "its outputs were compensated on board (calibration 7)" for a log of a compensating board (cal_state active or
/// settled, the latter adding "after a warm restart, the transient taken as over"); none otherwise, a log of no board
/// included.
std::optional<std::string> compensated_on_board(const LogMetadata& metadata);

}  // namespace driftlab::host
