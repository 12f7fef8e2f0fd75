// `driftlab gap-eval`: the withheld-effect benchmark of the gap diagnosis (host/gap_eval, docs/gap.md §Evaluation).
#include <unistd.h>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/cli/gap_eval_output.hpp"
#include "host/cli/shard_option.hpp"
#include "host/gap_eval/eval_parts.hpp"
#include "host/gap_eval/truth.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/output_folder.hpp"
#include "host/util/part_file.hpp"
#include "host/util/time_left.hpp"

namespace driftlab::host::cli {
namespace {

struct GapEvalCommandOptions {
    std::string tune_seeds = "1..4";
    std::string score_seeds = "101..104";
    std::vector<std::string> effects;
    gap::Holdout holdout = gap::BatteryOptions{}.holdout;
    std::vector<double> levels;
    std::vector<std::string> pairs;
    double pair_level = 2.0;
    int clean_per_seed = 0;
    bool quick = false;
    bool clean_only = false;
    bool raw_clean = false;
    bool codes_clean = false;
    bool link_clean = false;
    bool common_clean = false;
    std::size_t samples = 0;  // 0: the benchmark's 1500 (--quick: 800)
    int detection_logs = 0;   // 0: the benchmark's 48 (--quick: 4)
    bool shipped = false;
    bool json = false;
    std::string plot_dir;
    std::pair<std::size_t, std::size_t> shard{0, 1};  // K, N
    std::string part;                                 // -o: this shard's part file
    bool measure_sizes = false;                       // the first stage: a_50 of the shard's generators only
    std::string sizes_file;                           // --sizes: the first stage's merge
};

std::pair<std::uint64_t, std::uint64_t> parse_range(const std::string& flag, const std::string& s) {
    const auto refused = [&] {
        return UsageError(flag + ": expected A..B with whole numbers 0 <= A <= B <= " +
                          std::to_string(gap::kMaxEvalSeed) + ", got '" + s + "'");
    };
    // Digits only: std::stoull would take "-1" as 2^64 - 1.
    const auto number = [&](const std::string& text) {
        if (text.empty() || text.size() > 7 || text.find_first_not_of("0123456789") != std::string::npos)
            throw refused();
        return std::stoull(text);
    };
    const auto dots = s.find("..");
    if (dots == std::string::npos) throw refused();
    const std::uint64_t a = number(s.substr(0, dots)), b = number(s.substr(dots + 2));
    if (b < a || b > gap::kMaxEvalSeed) throw refused();
    return {a, b};
}

// A generator named by itself or by the library effect it stands for.
std::string generator_named(const std::string& flag, const std::string& name) {
    std::string known;
    for (const auto& t : gap::truth_list()) {
        // Not "": an out-of-library generator stands for no effect, and "" had named it.
        if (!name.empty() && (t.generator == name || t.effect == name)) return t.generator;
        known += (known.empty() ? "" : ", ") + t.generator +
                 (t.effect.empty() || t.effect == t.generator ? "" : " (" + t.effect + ")");
    }
    throw UsageError(flag + ": unknown generator or effect '" + name +
                     "' (generators, with the effect each stands for: " + known + ")");
}

std::vector<std::pair<std::string, std::string>> parse_pairs(const std::vector<std::string>& list) {
    std::vector<std::pair<std::string, std::string>> pairs;
    if (list.size() == 1 && list.front() == "none") return pairs;
    for (const std::string& p : list) {
        const auto plus = p.find('+');
        if (plus == std::string::npos) throw UsageError("--pairs: expected A+B, got '" + p + "'");
        // A+none plants A alone, diagnosed as `driftlab gap` runs: what its later steps add beside the right effect.
        const std::string second = p.substr(plus + 1);
        const std::string a = generator_named("--pairs", p.substr(0, plus));
        const std::string b = second == "none" ? second : generator_named("--pairs", second);
        if (const std::string why = gap::pair_refusal(a, b); !why.empty()) throw UsageError("--pairs: " + why);
        pairs.emplace_back(a, b);
    }
    return pairs;
}

// The first stage's shard: a_50 of the generators g with g mod N = K, in a sizes part for `merge -o SIZES`.
void write_sizes_shard(const GapEvalCommandOptions& o, gap::EvalOptions options) {
    std::tie(options.shard, options.shards) = o.shard;
    gap::SizesPart part{options, build_id(), gap::sized_generators(options).size(), {}, {}};
    for (std::size_t g = options.shard; g < part.generators; g += options.shards) part.items.push_back(g);
    part.sizes = gap::detection_sizes(options, options.shard, options.shards);
    gap::write_sizes_part(part, o.part);
    std::fprintf(stderr,
                 "gap-eval: sizes shard %zu/%zu: a_50 of %zu of %zu generators in %s (driftlab merge PART... -o SIZES "
                 "joins them)\n",
                 options.shard, options.shards, part.items.size(), part.generators, o.part.c_str());
}

// The campaign the command line asks for (its shard and progress aside).
gap::EvalOptions campaign_options(const GapEvalCommandOptions& o) {
    gap::EvalOptions options;
    std::tie(options.tune_first, options.tune_last) = parse_range("--seeds-tune", o.tune_seeds);
    std::tie(options.score_first, options.score_last) = parse_range("--seeds-score", o.score_seeds);
    for (std::size_t i = 0; i < o.levels.size(); ++i)
        for (std::size_t k = 0; k < i; ++k)
            if (o.levels[k] == o.levels[i])
                throw UsageError("--levels: " + format_double(o.levels[i]) + " is given twice (each size is one row)");
    for (const std::string& e : o.effects) options.generators.push_back(generator_named("--effects", e));
    // The full run plants the default pairs too; a run of chosen effects only those asked for.
    options.pairs = o.pairs.empty() ? (o.effects.empty() && !o.quick && !o.clean_only ? gap::default_pairs()
                                                                                      : decltype(options.pairs){})
                                    : parse_pairs(o.pairs);
    // After each option's own check, so that a misspelt effect is named even where the seeds overlap too. --clean-only
    // tunes nothing, so its tuning seeds (the default ones, unless given) are not run.
    if (!o.clean_only && !(options.score_first > options.tune_last || options.score_last < options.tune_first))
        throw UsageError("--seeds-tune and --seeds-score must not overlap");
    options.pair_level = o.pair_level;
    options.holdout = o.holdout;
    options.clean_per_seed = o.clean_per_seed;
    options.clean_form = o.raw_clean      ? gap::CleanForm::raw_mode
                         : o.codes_clean  ? gap::CleanForm::codes
                         : o.link_clean   ? gap::CleanForm::lossy_link
                         : o.common_clean ? gap::CleanForm::four_channels
                                          : gap::CleanForm::smoothed;
    if (o.quick) {
        options.samples = 800;
        options.levels = {2.0};
        options.detection_logs = 4;
        options.replicates = 16;
        options.fit_replicates = 6;
        options.max_evaluations = 12;
    }
    if (o.samples > 0) options.samples = o.samples;
    if (o.detection_logs > 0) options.detection_logs = o.detection_logs;
    if (!o.levels.empty()) options.levels = o.levels;
    // With the shipped thresholds the tuning seeds only measure a_50 (the thresholds were tuned on the default ones).
    options.tune = !(o.shipped || o.clean_only);
    if (o.clean_only) {
        // As many clean logs per seed as a run of every size has, unless asked; then nothing planted, no a_50.
        if (options.clean_per_seed == 0) options.clean_per_seed = static_cast<int>(options.levels.size());
        options.levels.clear();
    }
    return options;
}

// A stage's progress on a terminal ("gap-eval: WHAT done/total  time left"); none where stderr is not one.
std::function<void(std::size_t, std::size_t)> progress_for(const char* what) {
    if (!isatty(2)) return {};
    const auto started = std::chrono::steady_clock::now();
    return [what, started](std::size_t done, std::size_t total) {
        const double fraction = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
        std::fprintf(stderr, "\rgap-eval: %s %zu/%zu  %s\033[K", what, done, total,
                     time_left(fraction, seconds_since(started)).c_str());
        if (done == total) std::fprintf(stderr, "\n");
    };
}

void run(const GapEvalCommandOptions& o) {
    gap::EvalOptions options = campaign_options(o);
    // Before the run, so that an unwritable folder is reported at once rather than after it.
    if (!o.plot_dir.empty()) make_output_folder(o.plot_dir, "plot");
    options.progress = progress_for("detection threshold a_50, generator");
    if (o.measure_sizes) {
        write_sizes_shard(o, options);
        return;
    }
    const std::vector<gap::DetectionSize> sizes = o.clean_only           ? std::vector<gap::DetectionSize>{}
                                                  : o.sizes_file.empty() ? gap::detection_sizes(options)
                                                                         : gap::read_sizes(o.sizes_file, options);
    std::tie(options.shard, options.shards) = o.shard;
    options.progress = progress_for("diagnosing log");
    auto cases = gap::run_cases(options, sizes);
    options.progress = progress_for("diagnosing two-effect log");
    auto pair_cases = gap::run_pairs(options, sizes);
    if (o.part.empty()) {
        print_gap_eval(options, sizes, cases, pair_cases, o.json, o.plot_dir);
        return;
    }
    gap::EvalPart part{
        options,          build_id(),           sizes, gap::case_items(options), gap::pair_items(options),
        std::move(cases), std::move(pair_cases)};
    gap::write_part(part, o.part);
    std::fprintf(stderr, "gap-eval: shard %zu/%zu: %zu of %zu logs in %s (driftlab merge PART... scores them)\n",
                 options.shard, options.shards, part.cases.size() + part.pairs.size(),
                 part.cases_total + part.pairs_total, o.part.c_str());
}

std::string default_pairs_text() {
    std::string text;
    for (const auto& [a, b] : gap::default_pairs()) text += (text.empty() ? "" : ",") + a + "+" + b;
    return text;
}

// The options that shape the campaign's logs and scores.
void add_campaign_options(CLI::App* cmd, GapEvalCommandOptions* o) {
    cmd->add_option("--seeds-tune", o->tune_seeds, "Seeds the decision thresholds are tuned on, A..B");
    cmd->add_option("--seeds-score", o->score_seeds, "Seeds the results are scored on, C..D (disjoint)");
    CLI::Option* effects =
        cmd->add_option("--effects", o->effects, "Truth generators or the effects they stand for (default: all)")
            ->delimiter(',');
    // Beyond 16 x a_50 an effect swamps the log (a thermal network of 1000 x a_50 leaves the gyro no noise to
    // compare), and tells nothing about detection.
    CLI::Option* levels =
        cmd->add_option("--levels", o->levels,
                        "Effect sizes in multiples of each generator's a_50, at most 16 (default 0.5,1,2,4)")
            ->delimiter(',')
            ->check(number_in(0.0, 16.0, Bound::open));
    CLI::Option* pairs =
        cmd->add_option(
               "--pairs", o->pairs,
               "Two-effect logs: pairs A+B of generators (or effects) planted together, diagnosed as `driftlab gap` "
               "runs (A+none: A alone, so run); 'none' for none (default: " +
                   default_pairs_text() + " in a run of all effects, none with --effects)")
            ->delimiter(',');
    cmd->add_option("--pair-level", o->pair_level,
                    "Each of a pair at this multiple of its own a_50, at most 16 (default 2)")
        ->check(number_in(0.0, 16.0, Bound::open));
    cmd->add_option("--samples", o->samples,
                    "Outputs per log (default 1500; 14400 is an hour at 100 Hz smoothed 25 conversions to an output)")
        ->check(whole_number_in(200, 100000));
    cmd->add_option("--detection-logs", o->detection_logs, "Logs per size when measuring a_50 (default 48)")
        ->check(whole_number_in(4, 1000));
    cmd->add_option("--clean-per-seed", o->clean_per_seed,
                    "Clean logs per seed for the false-positive rate (default: as many as sizes)")
        ->check(whole_number_in(1, 1000));
    add_holdout_option(cmd, o->holdout);
    cmd->add_flag("--quick", o->quick, "Short logs, one size, fewer replicates");
    cmd->add_flag(
        "--shipped", o->shipped,
        "Score the thresholds `driftlab gap` ships instead of tuning them (the tuning seeds then only measure "
        "a_50): more scoring seeds for the same frozen thresholds");
    cmd->add_flag("--clean-only", o->clean_only,
                  "Clean logs only, scored with the thresholds `driftlab gap` ships (implies --shipped): the "
                  "false-positive rate on many seeds (no a_50)")
        ->excludes(effects)
        ->excludes(levels)
        ->excludes(pairs);
    auto* raw_clean = cmd->add_flag("--raw-clean", o->raw_clean,
                                    "Clean logs are raw-mode (a raw_gyro column, so their code-histogram cells are "
                                    "tested too), as sar_mismatch's logs are");
    cmd->add_flag("--codes-clean", o->codes_clean,
                  "Clean logs have outputs of one conversion each (window 1, no raw column: the outputs are the codes, "
                  "so their code-histogram cells are tested too), as sar_codes's logs are")
        ->excludes(raw_clean);
    cmd->add_flag(
           "--link-clean", o->link_clean,
           "Clean logs lose frames as the calibrated link does (each alone, 0.5 %) and are diagnosed against it, "
           "as interference_bursts's logs are")
        ->excludes(raw_clean);
    cmd->add_flag("--common-clean", o->common_clean,
                  "Clean logs record all four channels (the accelerometer axes drawn as the gyro is), so the channels "
                  "are also read together, as supply_wander's logs are")
        ->excludes(raw_clean);
}

}  // namespace

void register_gap_eval(CLI::App& app) {
    auto o = std::make_shared<GapEvalCommandOptions>();
    CLI::App* cmd = app.add_subcommand("gap-eval",
                                       "Benchmark the gap diagnosis on simulated logs with a withheld effect "
                                       "(truth generators differ from the fitted forms)");
    add_campaign_options(cmd, o.get());
    cmd->add_flag("--json", o->json,
                  "Print JSON instead of the markdown tables (keys: thresholds, a50, false_positive, confusion, "
                  "by_size, targets, pairs)");
    cmd->add_option(
           "--plot", o->plot_dir,
           "Also write DIR/gap_eval_detected and DIR/gap_eval_top1 (PNG, SVG): detected and right-verdict shares "
           "against size, with 95 % intervals")
        ->check(non_empty_path())
        ->excludes("--clean-only");
    CLI::Option* part = add_shard_options(cmd, o->shard, o->part, "logs")->excludes("--json")->excludes("--plot");
    CLI::Option* measure =
        cmd->add_flag("--measure-sizes", o->measure_sizes,
                      "With --shard K/N -o PART: only measure a_50, of the generators g with g mod N = K (the first "
                      "stage; `driftlab merge PART... -o SIZES` joins them for --sizes)")
            ->needs(part)
            ->excludes("--clean-only");
    cmd->add_option(
           "--sizes", o->sizes_file,
           "Read every generator's a_50 from SIZES (the first stage's merge) instead of measuring it: the same "
           "campaign options, the same build")
        ->check(CLI::ExistingFile)
        ->excludes(measure)
        ->excludes("--clean-only");
    cmd->callback([o] { run(*o); });
}

}  // namespace driftlab::host::cli
