// The withheld-effect benchmark behind `driftlab gap-eval`: simulate gyro logs of a domain-randomised base with
// one truth generator (truth.hpp; or none), hide it from the diagnosis, and score the verdicts. Decision
// thresholds (thresholds.hpp) are tuned on one seed set and scored on another.
// docs/gap.md §Evaluation.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "host/gap/explain.hpp"
#include "host/gap_eval/planted_log.hpp"

namespace driftlab::host::gap {

struct EvalOptions {
    std::uint64_t tune_first = 1, tune_last = 4;  ///< seeds the thresholds are tuned on
    bool tune = true;  ///< false: no tuning logs; the thresholds `driftlab gap` ships are scored (Thresholds{})
    std::uint64_t score_first = 101, score_last = 104;  ///< seeds they are scored on (disjoint)
    std::vector<std::string> generators;  ///< truth generators (truth_list()); empty = all; "none" is always added
    std::vector<double> levels{0.5, 1.0, 2.0, 4.0};  ///< effect sizes, in multiples of each generator's a_50
    int clean_per_seed = 0;  ///< clean logs per seed (0: as many as levels): the false-positive rate's sample
    /// Clean logs raw-mode, or of outputs that are codes (their code-histogram cells tested), as a converter's are.
    CleanForm clean_form = CleanForm::smoothed;
    /// Logs per size when measuring a_50 (tuning seeds). The targets are read at 2 x a_50: with 12 logs per size one
    /// estimate stood 18 % above that of 48 (student_walk 1.16 against 0.95), which moves every log of a table.
    int detection_logs = 48;
    std::size_t samples = 1500;  ///< log length at 1 s per sample
    Holdout holdout = BatteryOptions{}.holdout;
    int replicates = 20;
    int fit_replicates = ExplainOptions{}.fit_replicates;  ///< as `driftlab gap` ships
    int max_evaluations = ExplainOptions{}.max_evaluations;
    /// Two-effect logs: each pair of truth generators planted together, each at `pair_level` x its own a_50, on the
    /// scoring seeds, diagnosed as `driftlab gap` runs (its shipped thresholds, effects added stepwise). Converter
    /// generators (sar_mismatch) replace the quantiser and out-of-library ones (mode_hop) have no effect to find:
    /// neither is paired. A second generator "none" plants the first alone: a single-effect log diagnosed as `driftlab
    /// gap` runs, which shows the effects its later steps add beside the right one.
    std::vector<std::pair<std::string, std::string>> pairs;
    double pair_level = 2.0;
    int threads = 2;  ///< logs diagnosed at once, one thread each (the verdicts do not depend on it)
    /// This run's shard of the campaign (eval_parts.hpp): the items i with i mod shards == shard.
    std::size_t shard = 0, shards = 1;
    std::function<void(std::size_t done, std::size_t total)>
        progress;  ///< optional; called from those threads, one at a time
};

/// Why `first`+`second` cannot be planted as a pair (EvalOptions::pairs), or "" when it can: two distinct generators of
/// library effects acting at the converter input, or the first alone (second "none"). Throws std::invalid_argument on
/// an unknown generator.
std::string pair_refusal(const std::string& first, const std::string& second);

/// The pairs a full run plants together (no --effects): two mean shapes (a thermostat's cycle over a board's slow
/// warm-up), a mean shape on a noise process, a mean shape on a heavy-tailed walk, and a process with events.
std::vector<std::pair<std::string, std::string>> default_pairs();

/// One size of a detection curve: logs planted at `size`, and how many of them got located cells.
struct DetectionPoint {
    double size = 0.0;
    int detected = 0;
    int logs = 0;
};

/// A generator's detection threshold a_50: the size at which the located-cells stage flags half of the logs,
/// in units of the smoothed output's white-noise standard deviation, with the measured detection curve.
struct DetectionSize {
    std::string generator;
    double a50 = 1.0;
    std::vector<DetectionPoint> curve;  ///< by size
};

/// a_50 of a detection curve by maximum likelihood of the logistic model P(detected | s) = 1 / (1 + e^-(a + b ln s)):
/// exp(-a / b). Every point carries a quarter of a pseudo-detection and of a pseudo-miss, so that a curve that
/// jumps from none to all still has a finite slope. Empty when the fitted slope is not positive.
std::optional<double> logistic_a50(const std::vector<DetectionPoint>& curve);

/// The generators whose a_50 a campaign measures, in order: the run's, then those only its pairs plant.
std::vector<std::string> sized_generators(const EvalOptions& options);

/// Measures a_50 of the generators g of sized_generators() with g mod shards == shard (all by default) on the tuning
/// seeds (locate-only diagnoses): doubling or halving from a first guess until the detected fraction crosses 1/2, two
/// more sizes half an octave either side of the crossing, then the logistic fit over every size tried (the crossing's
/// interpolation where the fit fails). A generator's logs come from its place in truth_list(), never from the shard.
std::vector<DetectionSize> detection_sizes(const EvalOptions& options, std::size_t shard = 0, std::size_t shards = 1);

/// One simulated log and what the diagnosis said about it.
struct EvalCase {
    std::size_t item = 0;   ///< its place among the logs the run diagnoses (eval_parts.hpp)
    std::string generator;  ///< truth generator or "none"
    std::string truth;      ///< the library effect it stands for, "none", or "" (out of library)
    double level = 0.0;     ///< size in multiples of the generator's a_50
    double size_counts = 0.0;
    std::uint64_t seed = 0;
    bool tune = false;               ///< in the tuning set
    bool detected = false;           ///< located cells were found (of the channels or the link)
    bool link_only = false;          ///< ... of the link alone
    std::string link_verdict;        ///< the link's added candidate, or ""
    std::string common_verdict;      ///< the shared reading that won (channels read together), or ""
    std::vector<Explanation> tried;  ///< every candidate with its metrics (thresholds applied later)
    double shrink_check = 0.0;       ///< held-out shrink of the truth's candidate re-measured on fresh replicates
    bool has_shrink_check = false;   ///< only where the run-time diagnosis, every candidate kept, put the truth first
    double oracle_shrink = 0.0;      ///< held-out shrink with the TRUE model: the truth base plus fresh realisations
    bool has_oracle = false;         ///< of the truth generator at its planted size (planted, detected cases)
};

/// A log with two truth generators planted together, and what the diagnosis made of it.
struct PairCase {
    std::size_t item = 0;       ///< its place in the campaign: after every case (eval_parts.hpp)
    std::string first, second;  ///< truth generators (second "none": the first alone)
    double level = 0.0;         ///< each at this multiple of its own a_50
    std::uint64_t seed = 0;
    bool detected = false;
    std::string verdict;                   ///< the diagnosis's verdict: its first added effect, "none" or "unexplained"
    std::vector<std::string> added;        ///< every effect added stepwise, in order
    std::vector<std::string> close_calls;  ///< per added effect, its declared close call ("" for none)
    std::vector<bool> within_bound;        ///< per added effect, Explanation::within_bound_before()
    double heldout_before = 1.0, heldout_after = 1.0;  ///< held-out gap score of the base and of the final model
};

/// The logs run_cases() and run_pairs() diagnose in a whole campaign (every shard).
std::size_t case_items(const EvalOptions& options);
std::size_t pair_items(const EvalOptions& options);

/// The shard (of options.shards) that diagnoses each item of the campaign, the cases' then the pairs': the items
/// grouped by what they plant (a generator at a size, a pair) and dealt round-robin group after group, so that every
/// shard gets an even share of every kind of log. The kinds differ in cost several times over, and item i mod N had
/// given each shard whole generators (every seed lists them in one order): one of two shards took 1.5 x the other.
std::vector<std::size_t> item_shards(const EvalOptions& options);

/// Runs every case (tuning and scoring seeds) of the shard, planting each generator at level x its a_50 from `sizes`.
std::vector<EvalCase> run_cases(const EvalOptions& options, const std::vector<DetectionSize>& sizes);

/// The two-effect logs of `options.pairs` (scoring seeds; their seeds are apart from run_cases()', so adding pairs
/// to a run changes none of its other logs).
std::vector<PairCase> run_pairs(const EvalOptions& options, const std::vector<DetectionSize>& sizes);

/// The largest seed a run takes (gap-eval refuses larger ones): its logs' seeds, seed * 1009 + place, then stay
/// below 2^32, under the two-effect logs' (seed << 32).
inline constexpr std::uint64_t kMaxEvalSeed = 1000000;

/// Where a log whose seed * 1009 + place an earlier log of the run already took is moved (case_seeds()).
inline constexpr std::uint64_t kMovedCaseSeed = std::uint64_t{1} << 62;

/// The seed of each log of a run from its seed in the run's order: seed * 1009 + its place, so that a log is the same
/// in every run that puts it in the same place; a log whose value an earlier one took gets kMovedCaseSeed + place
/// instead, so that no two logs share one.
std::vector<std::uint64_t> case_seeds(const std::vector<std::uint64_t>& run_seeds);

}  // namespace driftlab::host::gap
