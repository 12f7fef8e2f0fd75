// A fleet in shards and their merge; see fleet_parts.hpp.
#include "host/fleet/fleet_parts.hpp"

#include <numeric>

#include "host/fleet/board_json.hpp"
#include "host/util/error.hpp"
#include "host/util/part_file.hpp"

namespace driftlab::host::fleet {
namespace {

constexpr int kPartFormat = 1;

FleetPart read_fleet_part(const std::string& path) {
    const nlohmann::json j = read_part_file(path, kFleetPartKind, kPartFormat, "driftlab fleet --shard K/N -o PART");
    try {
        FleetPart p;
        p.campaign = j.at("campaign");
        j.at("build").get_to(p.build);
        j.at("shard").get_to(p.shard);
        j.at("shards").get_to(p.shards);
        j.at("items").get_to(p.items);
        j.at("boards").get_to(p.boards);
        if (p.items.size() != p.boards.size())
            throw DataError(path, 0, "a damaged fleet part: items and boards differ");
        return p;
    } catch (const nlohmann::json::exception& e) {
        throw DataError(path, 0, std::string("a damaged fleet part: ") + e.what());
    }
}

}  // namespace

void write_fleet_part(const FleetPart& part, const std::string& path) {
    write_part_file({{"kind", kFleetPartKind},
                     {"format", kPartFormat},
                     {"build", part.build},
                     {"campaign", part.campaign},
                     {"shard", part.shard},
                     {"shards", part.shards},
                     {"items", part.items},
                     {"boards", part.boards}},
                    path);
}

FleetPart merge_fleet_parts(const std::vector<std::string>& paths) {
    if (paths.empty()) throw DataError("merge", 0, "no part given");
    FleetPart whole = read_fleet_part(paths.front());
    const std::size_t n = whole.shards;
    const std::size_t logs = whole.campaign.at("logs").size();
    ShardSet shards(n, whole.build);
    ItemSlots<BoardEntry> boards(logs, "board");
    for (const std::string& path : paths) {
        FleetPart part = path == paths.front() ? whole : read_fleet_part(path);
        if (part.campaign != whole.campaign)
            throw DataError(path, 0, "of another fleet: its logs or options differ (" + part.campaign.dump() + ")");
        shards.add(part.shard, part.shards, part.build, path);
        for (std::size_t i = 0; i < part.items.size(); ++i)
            boards.put(part.items[i], part.shard, part.items[i] % n, std::move(part.boards[i]), path);
    }
    shards.check_complete(paths.front());
    whole.boards = boards.take(paths.front());
    whole.items.resize(logs);
    std::iota(whole.items.begin(), whole.items.end(), std::size_t{0});
    whole.shard = 0;
    whole.shards = 1;
    return whole;
}

}  // namespace driftlab::host::fleet
