// A gap-eval campaign in shards and their merge; see eval_parts.hpp.
#include "host/gap_eval/eval_parts.hpp"

#include <algorithm>
#include <numeric>

#include <nlohmann/json.hpp>

#include "host/util/error.hpp"
#include "host/util/part_file.hpp"

namespace driftlab {
NLOHMANN_JSON_SERIALIZE_ENUM(Channel, {{Channel::gyro, "gyro"},
                                       {Channel::accel_x, "accel_x"},
                                       {Channel::accel_y, "accel_y"},
                                       {Channel::accel_z, "accel_z"}})
}  // namespace driftlab

namespace driftlab::host::gap {

NLOHMANN_JSON_SERIALIZE_ENUM(Holdout, {{Holdout::forecast, "forecast"}, {Holdout::interleaved, "interleaved"}})
NLOHMANN_JSON_SERIALIZE_ENUM(CleanForm, {{CleanForm::smoothed, "smoothed"},
                                         {CleanForm::raw_mode, "raw_mode"},
                                         {CleanForm::codes, "codes"},
                                         {CleanForm::lossy_link, "lossy_link"},
                                         {CleanForm::four_channels, "four_channels"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(StepEstimate, t_s, size_counts)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LevelStep, tested, channel, steps, impulse, impulse_p, statistic, margin, rival_p,
                                   p_value, process_gain, process_margin, process_beside_steps, significant, outsized)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(StepsOverShape, tested, steps, statistic, margin, steps_win)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Explanation, effect, channel, params, gap_before, gap_after, heldout_before,
                                   heldout_after, heldout_shrink, heldout_bound, loss_gain, penalty, heldout_loss_gain,
                                   heldout_cell_loss, gaussian, spectral_gain, spectral_extra_parameters,
                                   spectral_observations, spectral_terms, long_memory, cells_left, residual_step,
                                   shape_steps, accepted, step, replaces_given, whole_log_params, ambiguous_with,
                                   settle)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(EvalCase, item, generator, truth, level, size_counts, seed, tune, detected,
                                   link_only, link_verdict, common_verdict, tried, shrink_check, has_shrink_check,
                                   oracle_shrink, has_oracle)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(PairCase, item, first, second, level, seed, detected, verdict, added, close_calls,
                                   within_bound, heldout_before, heldout_after)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(DetectionPoint, size, detected, logs)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(DetectionSize, generator, a50, curve)

namespace {

constexpr const char* kKind = kEvalPartKind;
constexpr int kFormat = 1;

// The campaign's options as a part records them: everything that shapes its logs and scores (not the threads, which
// change nothing, nor the shard, which a part states apart). One list for writing and reading.
// clang-format re-wraps an X-macro's list differently on every pass: the list is left as written.
// clang-format off
#define DRIFTLAB_CAMPAIGN_OPTIONS(X)                                                                   \
    X(tune_first) X(tune_last) X(tune) X(score_first) X(score_last) X(generators) X(levels)            \
    X(clean_per_seed) X(clean_form) X(detection_logs) X(samples) X(holdout) X(replicates)              \
    X(fit_replicates) X(max_evaluations) X(pairs) X(pair_level)
// clang-format on

nlohmann::json options_json(const EvalOptions& o) {
    nlohmann::json j;
#define DRIFTLAB_PUT(field) j[#field] = o.field;
    DRIFTLAB_CAMPAIGN_OPTIONS(DRIFTLAB_PUT)
#undef DRIFTLAB_PUT
    return j;
}

EvalOptions options_from(const nlohmann::json& j) {
    EvalOptions o;
#define DRIFTLAB_GET(field) j.at(#field).get_to(o.field);
    DRIFTLAB_CAMPAIGN_OPTIONS(DRIFTLAB_GET)
#undef DRIFTLAB_GET
    return o;
}

#undef DRIFTLAB_CAMPAIGN_OPTIONS

}  // namespace

void write_part(const EvalPart& part, const std::string& path) {
    write_part_file({{"kind", kKind},
                     {"format", kFormat},
                     {"build", part.build},
                     {"options", options_json(part.options)},
                     {"shard", part.options.shard},
                     {"shards", part.options.shards},
                     {"cases_total", part.cases_total},
                     {"pairs_total", part.pairs_total},
                     {"sizes", part.sizes},
                     {"cases", part.cases},
                     {"pairs", part.pairs}},
                    path);
}

EvalPart read_part(const std::string& path) {
    const nlohmann::json j = read_part_file(path, kKind, kFormat, "driftlab gap-eval --shard K/N -o PART");
    try {
        EvalPart part;
        part.options = options_from(j.at("options"));
        j.at("shard").get_to(part.options.shard);
        j.at("shards").get_to(part.options.shards);
        j.at("build").get_to(part.build);
        j.at("cases_total").get_to(part.cases_total);
        j.at("pairs_total").get_to(part.pairs_total);
        j.at("sizes").get_to(part.sizes);
        j.at("cases").get_to(part.cases);
        j.at("pairs").get_to(part.pairs);
        return part;
    } catch (const nlohmann::json::exception& e) {
        throw DataError(path, 0, std::string("a damaged gap-eval part: ") + e.what());
    }
}

namespace {

// Why `part` (from `path`) is not of the campaign `first` is, or "" (the build and shard count: ShardSet).
std::string foreign(const EvalPart& part, const EvalPart& first) {
    if (options_json(part.options) != options_json(first.options))
        return "of another campaign: its options differ (" + options_json(part.options).dump() + ")";
    if (part.cases_total != first.cases_total || part.pairs_total != first.pairs_total)
        return "of a campaign of other size";
    return "";
}

}  // namespace

EvalPart merge_parts(const std::vector<std::string>& paths) {
    if (paths.empty()) throw DataError("merge", 0, "no part given");
    EvalPart whole = read_part(paths.front());
    const std::size_t n = whole.options.shards;
    ShardSet shards(n, whole.build);
    const std::vector<std::size_t> shard_of = item_shards(whole.options);
    const auto owner = [&](std::size_t item) { return item < shard_of.size() ? shard_of[item] : n; };
    ItemSlots<EvalCase> cases(whole.cases_total, "item");
    ItemSlots<PairCase> pairs(whole.pairs_total, "item", whole.cases_total);
    for (const std::string& path : paths) {
        EvalPart part = path == paths.front() ? whole : read_part(path);
        if (const std::string why = foreign(part, whole); !why.empty()) throw DataError(path, 0, why);
        const std::size_t k = part.options.shard;
        shards.add(k, part.options.shards, part.build, path);
        for (auto& c : part.cases) cases.put(c.item, k, owner(c.item), std::move(c), path);
        for (auto& p : part.pairs) pairs.put(p.item, k, owner(p.item), std::move(p), path);
    }
    shards.check_complete(paths.front());
    whole.cases = cases.take(paths.front());
    whole.pairs = pairs.take(paths.front());
    whole.options.shard = 0;
    whole.options.shards = 1;
    return whole;
}

namespace {

SizesPart read_sizes_part(const std::string& path) {
    const nlohmann::json j =
        read_part_file(path, kSizesPartKind, kFormat, "driftlab gap-eval --measure-sizes --shard K/N -o PART");
    try {
        SizesPart part;
        part.options = options_from(j.at("options"));
        j.at("shard").get_to(part.options.shard);
        j.at("shards").get_to(part.options.shards);
        j.at("build").get_to(part.build);
        j.at("generators").get_to(part.generators);
        j.at("items").get_to(part.items);
        j.at("sizes").get_to(part.sizes);
        if (part.items.size() != part.sizes.size())
            throw DataError(path, 0, "a damaged sizes part: items and sizes differ");
        return part;
    } catch (const nlohmann::json::exception& e) {
        throw DataError(path, 0, std::string("a damaged sizes part: ") + e.what());
    }
}

}  // namespace

void write_sizes_part(const SizesPart& part, const std::string& path) {
    write_part_file({{"kind", kSizesPartKind},
                     {"format", kFormat},
                     {"build", part.build},
                     {"options", options_json(part.options)},
                     {"shard", part.options.shard},
                     {"shards", part.options.shards},
                     {"generators", part.generators},
                     {"items", part.items},
                     {"sizes", part.sizes}},
                    path);
}

SizesPart merge_sizes_parts(const std::vector<std::string>& paths) {
    if (paths.empty()) throw DataError("merge", 0, "no part given");
    SizesPart whole = read_sizes_part(paths.front());
    const std::size_t n = whole.options.shards;
    ShardSet shards(n, whole.build);
    ItemSlots<DetectionSize> sizes(whole.generators, "generator");
    for (const std::string& path : paths) {
        SizesPart part = path == paths.front() ? whole : read_sizes_part(path);
        if (options_json(part.options) != options_json(whole.options) || part.generators != whole.generators)
            throw DataError(path, 0,
                            "of another campaign: its options differ (" + options_json(part.options).dump() + ")");
        const std::size_t k = part.options.shard;
        shards.add(k, part.options.shards, part.build, path);
        for (std::size_t i = 0; i < part.items.size(); ++i)
            sizes.put(part.items[i], k, part.items[i] % n, std::move(part.sizes[i]), path);
    }
    shards.check_complete(paths.front());
    whole.sizes = sizes.take(paths.front());
    whole.items.resize(whole.generators);
    std::iota(whole.items.begin(), whole.items.end(), std::size_t{0});
    whole.options.shard = 0;
    whole.options.shards = 1;
    return whole;
}

std::vector<DetectionSize> read_sizes(const std::string& path, const EvalOptions& options) {
    SizesPart part = read_sizes_part(path);
    if (part.options.shards != 1)
        throw DataError(path, 0,
                        "shard " + std::to_string(part.options.shard) + " of " + std::to_string(part.options.shards) +
                            " of the sizes: give their merge (driftlab merge PART... -o SIZES)");
    if (part.build != build_id()) throw DataError(path, 0, "made by another build of driftlab (" + part.build + ")");
    if (options_json(part.options) != options_json(options))
        throw DataError(
            path, 0, "the sizes of another campaign: its options differ (" + options_json(part.options).dump() + ")");
    return std::move(part.sizes);
}

}  // namespace driftlab::host::gap
