// What makes a fleet resumable (docs/fleet.md §Resuming): each board's result kept under a key of its log's bytes,
// the options that shape the analysis and the build, so that a log analysed before with the same options is read
// back, not analysed again — after an interrupted run, a log added to the batch, or a shard re-run by the scheduler.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "host/fleet/board.hpp"

namespace driftlab::host::fleet {

/// The key of `log`'s analysis under `options` (what shapes it, as a document); "" when the log cannot be read.
std::string board_key(const std::string& log, const nlohmann::json& options);

/// The result kept under `key` in `dir`, if any; a damaged entry is none (the board is analysed again).
std::optional<BoardResult> cached_board(const std::string& dir, const std::string& key);

/// Keeps `result` under `key` in `dir` (created if needed), written whole. Throws DeviceError naming the file.
void store_board(const std::string& dir, const std::string& key, const BoardResult& result);

/// Where results are kept without --cache: $XDG_CACHE_HOME/driftlab/fleet, else ~/.cache/driftlab/fleet; "" when
/// neither variable is set.
std::string default_cache_dir();

}  // namespace driftlab::host::fleet
