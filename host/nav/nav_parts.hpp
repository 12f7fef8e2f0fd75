// A nav-eval campaign in shards (`nav-eval --shard K/N -o PART`) and their merge (`driftlab merge`). The campaign's
// items are its seeds, first + i for i = 0 .. runs - 1: each is one rest recording its drift is fitted on and a run
// along every trajectory, so item i (every trajectory of seed first + i) is shard i mod N's, its logs simulated from
// the seed alone. A part holds its runs' scores (CBOR, exact), the campaign as the command states it and the build;
// the merge checks that the parts are one campaign, complete, without repeats. docs/cluster.md.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "host/nav/nav_eval.hpp"

namespace driftlab::host::nav {

struct NavPart {
    nlohmann::json campaign;  ///< every option that shapes the runs (the model file's text among them)
    std::string build;        ///< host::build_id()
    std::size_t shard = 0, shards = 1;
    std::size_t seeds = 0;      ///< the campaign's items
    std::vector<EvalRun> runs;  ///< the shard's, seed by seed, each seed's trajectories in the campaign's order
};

void write_nav_part(const NavPart& part, const std::string& path);

/// The whole campaign from its parts, the runs in the one-process run's order. Throws DataError naming a part that
/// is not one, of another campaign or build, a repeated or missing shard, or one holding another shard's seeds.
NavPart merge_nav_parts(const std::vector<std::string>& paths);

/// The kind a nav-eval part file states (host::part_kind()).
inline constexpr const char* kNavPartKind = "nav-eval part";

}  // namespace driftlab::host::nav
