// A gap-eval campaign in shards (`--shard K/N -o PART`) and their merge (`driftlab merge`). The campaign's items are
// its logs in the one-process run's order: the cases (run_cases()), then the two-effect logs (run_pairs());
// item_shards() deals them to the shards. A log's seed comes from the campaign's seeds and its item's place, never from
// K or N, so a log is the same in every split. Every shard measures the detection thresholds a_50 itself (the same on
// each: the same tuning logs), unless a first stage measured them once: its shards (`--measure-sizes --shard K/N`) each
// measure the generators g with g mod N = K, and their merge is the sizes file every case shard reads (`--sizes`). A
// part holds its shard's diagnosed logs whole (CBOR, every double exact), the campaign's options and the build that ran
// it; the merge checks that the parts are one campaign, complete and without repeats, and gives back what the
// one-process run scores. docs/cluster.md.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "host/gap_eval/evaluate.hpp"

namespace driftlab::host::gap {

/// What one shard of a campaign did, or (shard 0 of 1) the whole campaign.
struct EvalPart {
    EvalOptions options;  ///< the campaign's (progress and threads aside); options.shard says which part
    std::string build;    ///< the build that ran it (host::build_id())
    std::vector<DetectionSize> sizes;
    std::size_t cases_total = 0, pairs_total = 0;  ///< the campaign's items of each kind
    std::vector<EvalCase> cases;                   ///< this shard's, with their items
    std::vector<PairCase> pairs;
};

/// Writes `part` to `path` whole (host/util/part_file.hpp). Throws DeviceError naming the path.
void write_part(const EvalPart& part, const std::string& path);

/// Reads a part. Throws DataError naming the file when it is not a gap-eval part of this format.
EvalPart read_part(const std::string& path);

/// The whole campaign from its parts (in any order): refuses, naming the file, a part of another campaign (options),
/// another build, a repeated or missing shard, or a part whose items disagree with its shard. Throws DataError.
EvalPart merge_parts(const std::vector<std::string>& paths);

/// The first stage's share: a_50 of the generators `items` (places in sized_generators()) of one shard, or of all of
/// them (shard 0 of 1: a sizes file).
struct SizesPart {
    EvalOptions options;
    std::string build;
    std::size_t generators = 0;  ///< the campaign's, sized_generators().size()
    std::vector<std::size_t> items;
    std::vector<DetectionSize> sizes;
};

void write_sizes_part(const SizesPart& part, const std::string& path);

/// Every generator's a_50 from the first stage's parts (in any order), as one sizes part of shard 0 of 1. Refuses, as
/// merge_parts() does, naming the file.
SizesPart merge_sizes_parts(const std::vector<std::string>& paths);

/// The a_50 of a sizes file (a merged first stage, or its one shard of 1) for the campaign `options`, made by this
/// build. Throws DataError naming the file when it is none, incomplete, of another campaign or another build.
std::vector<DetectionSize> read_sizes(const std::string& path, const EvalOptions& options);

/// The kinds a part file of either stage states (host::part_kind()).
inline constexpr const char* kEvalPartKind = "gap-eval part";
inline constexpr const char* kSizesPartKind = "gap-eval sizes part";

}  // namespace driftlab::host::gap
