// A fleet's boards analysed one after another (`driftlab fleet`, docs/fleet.md): each log read against the unit,
// analysed (host/fleet/board) or read back from the cache, a log that cannot be read kept with its reason while the
// rest go on. With shards, board i is shard i mod N's.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "host/fleet/batch.hpp"
#include "host/fleet/board.hpp"

namespace driftlab::host::fleet {

struct FleetOptions {
    BoardOptions board;
    std::string model_path;  ///< the unit the boards are built to; "" = the paper's
    std::string cache_dir;   ///< where results are kept (board_cache); "" = nowhere
};

/// The logs `inputs` name: a file as given, a folder as its *.csv files (not the *.truth.csv beside a log in
/// motion) sorted by name. Throws UsageError naming an input that does not exist or a folder without a log.
std::vector<std::string> fleet_logs(const std::vector<std::string>& inputs);

/// What shapes every board's analysis, as a document: the cache's key and a part's campaign hold it.
nlohmann::json analysis_options(const FleetOptions& options);

/// Told before each board: boards done, the shard's boards, the next log.
using FleetProgress = std::function<void(std::size_t done, std::size_t total, const std::string& log)>;

struct FleetRun {
    std::vector<std::size_t> items;  ///< each board's index in the fleet's logs
    std::vector<BoardEntry> boards;
    std::size_t from_cache = 0;  ///< boards read back, not analysed
};

/// Analyses logs[i] for every i with i mod shards == shard, in order.
FleetRun run_fleet(const std::vector<std::string>& logs, const FleetOptions& options, std::size_t shard,
                   std::size_t shards, const FleetProgress& progress = {});

}  // namespace driftlab::host::fleet
