// A nav-eval campaign in shards and their merge; see nav_parts.hpp.
#include "host/nav/nav_parts.hpp"

#include <cstdint>

#include "host/util/error.hpp"
#include "host/util/part_file.hpp"

namespace driftlab::host::nav {

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(VariantScore, name, heading_error_deg, position_error_m, final_heading_error_deg,
                                   final_position_error_m, heading_drift_deg_per_min, position_error_pct,
                                   nees_inside_fraction)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(NavScore, at_s, duration_s, distance_m, nees_dof, variants)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(EvalRun, trajectory, seed, score)

namespace {

constexpr int kFormat = 1;

NavPart read_nav_part(const std::string& path) {
    const nlohmann::json j = read_part_file(path, kNavPartKind, kFormat, "driftlab nav-eval --shard K/N -o PART");
    try {
        NavPart p;
        p.campaign = j.at("campaign");
        j.at("build").get_to(p.build);
        j.at("shard").get_to(p.shard);
        j.at("shards").get_to(p.shards);
        j.at("seeds").get_to(p.seeds);
        j.at("runs").get_to(p.runs);
        return p;
    } catch (const nlohmann::json::exception& e) {
        throw DataError(path, 0, std::string("a damaged nav-eval part: ") + e.what());
    }
}

// The runs of one seed each, in the part's order, checked to be the campaign's trajectories once each in its order.
std::vector<std::vector<EvalRun>> runs_by_seed(std::vector<EvalRun>&& runs,
                                               const std::vector<std::string>& trajectories, const std::string& path) {
    std::vector<std::vector<EvalRun>> out;
    for (EvalRun& r : runs) {
        if (out.empty() || out.back().front().seed != r.seed) out.emplace_back();
        out.back().push_back(std::move(r));
    }
    for (const auto& seed : out) {
        std::vector<std::string> names;
        for (const EvalRun& r : seed) names.push_back(r.trajectory);
        if (names != trajectories)
            throw DataError(path, 0,
                            "holds runs of seed " + std::to_string(seed.front().seed) +
                                " that are not the campaign's trajectories, each once in order");
    }
    return out;
}

}  // namespace

void write_nav_part(const NavPart& part, const std::string& path) {
    write_part_file({{"kind", kNavPartKind},
                     {"format", kFormat},
                     {"build", part.build},
                     {"campaign", part.campaign},
                     {"shard", part.shard},
                     {"shards", part.shards},
                     {"seeds", part.seeds},
                     {"runs", part.runs}},
                    path);
}

NavPart merge_nav_parts(const std::vector<std::string>& paths) {
    if (paths.empty()) throw DataError("merge", 0, "no part given");
    NavPart whole = read_nav_part(paths.front());
    const std::size_t n = whole.shards;
    const std::uint64_t first = whole.campaign.at("seed").get<std::uint64_t>();
    const auto trajectories = whole.campaign.at("trajectories").get<std::vector<std::string>>();
    ShardSet shards(n, whole.build);
    ItemSlots<std::vector<EvalRun>> seeds(whole.seeds, "seed", first);
    for (const std::string& path : paths) {
        NavPart part = path == paths.front() ? whole : read_nav_part(path);
        if (part.campaign != whole.campaign || part.seeds != whole.seeds)
            throw DataError(path, 0, "of another campaign: its options differ (" + part.campaign.dump() + ")");
        shards.add(part.shard, part.shards, part.build, path);
        for (auto& runs : runs_by_seed(std::move(part.runs), trajectories, path)) {
            const std::uint64_t seed = runs.front().seed;
            seeds.put(seed, part.shard, (seed - first) % n, std::move(runs), path);
        }
    }
    shards.check_complete(paths.front());
    whole.runs.clear();
    for (auto& runs : seeds.take(paths.front()))
        for (auto& r : runs) whole.runs.push_back(std::move(r));
    whole.shard = 0;
    whole.shards = 1;
    return whole;
}

}  // namespace driftlab::host::nav
