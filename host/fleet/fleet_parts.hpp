// A fleet in shards (`fleet --shard K/N -o PART`) and their merge (`driftlab merge`): board i of the fleet's logs is
// shard i mod N's; a part holds its boards' results (CBOR, exact), the fleet as the command states it (its logs and
// the analysis options) and the build. docs/cluster.md.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "host/fleet/batch.hpp"

namespace driftlab::host::fleet {

struct FleetPart {
    nlohmann::json campaign;  ///< {"logs": [...], "options": analysis_options()}
    std::string build;        ///< host::build_id()
    std::size_t shard = 0, shards = 1;
    std::vector<std::size_t> items;  ///< each board's index in campaign["logs"]
    std::vector<BoardEntry> boards;
};

void write_fleet_part(const FleetPart& part, const std::string& path);

/// The whole fleet from its parts, its boards in the logs' order. Throws DataError naming a part that is not one, of
/// another fleet or build, a repeated or missing shard, or one holding another shard's boards.
FleetPart merge_fleet_parts(const std::vector<std::string>& paths);

/// The kind a fleet part file states (host::part_kind()).
inline constexpr const char* kFleetPartKind = "fleet part";

}  // namespace driftlab::host::fleet
