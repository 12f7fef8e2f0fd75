// A nav-eval campaign in shards and their merge; see nav_parts.hpp.
#include "host/nav/nav_parts.hpp"

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
    const std::size_t per_seed = whole.campaign.at("trajectories").size();
    ShardSet shards(n, whole.build);
    std::vector<std::vector<EvalRun>> by_seed(whole.seeds);
    for (const std::string& path : paths) {
        NavPart part = path == paths.front() ? whole : read_nav_part(path);
        if (part.campaign != whole.campaign || part.seeds != whole.seeds)
            throw DataError(path, 0, "of another campaign: its options differ (" + part.campaign.dump() + ")");
        const std::size_t k = part.shard;
        shards.add(k, part.shards, part.build, path);
        for (EvalRun& r : part.runs) {
            const std::size_t item = static_cast<std::size_t>(r.seed - first);
            if (r.seed < first || item >= whole.seeds || item % n != k)
                throw DataError(path, 0,
                                "holds seed " + std::to_string(r.seed) + ", not shard " + std::to_string(k) + "'s");
            by_seed[item].push_back(std::move(r));
        }
    }
    shards.check_complete(paths.front());
    whole.runs.clear();
    for (auto& runs : by_seed) {
        if (runs.size() != per_seed) throw DataError(paths.front(), 0, "its campaign's parts miss runs of a seed");
        for (auto& r : runs) whole.runs.push_back(std::move(r));
    }
    whole.shard = 0;
    whole.shards = 1;
    return whole;
}

}  // namespace driftlab::host::nav
