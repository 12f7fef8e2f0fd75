// The scores of a withheld-effect benchmark run (gap-eval), computed once from its cases under the tuned thresholds
// (rendered by host/view/gap_eval_view.hpp). docs/gap.md §Evaluation.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "host/gap_eval/thresholds.hpp"

namespace driftlab::host::gap {

/// One truth generator at one size, over the scoring seeds.
struct SizeScore {
    std::string generator;
    std::string truth;   ///< library effect, "none" or "" (out of library)
    double level = 0.0;  ///< size in multiples of a_50
    int logs = 0, detected = 0;
    int top1 = 0;     ///< right verdicts
    int or_pair = 0;  ///< right verdicts or declared close calls holding the truth
    /// Medians (the upper middle value of an even count) of the held-out shrink: predicted by the diagnosis and
    /// |predicted - oracle| where the verdict is right under the scored thresholds; re-measured on fresh replicates
    /// where the permissive run-time diagnosis (EvalCase::has_shrink_check) put the truth first; of the oracle (true
    /// model) on every detected log, since it does not depend on the verdict.
    std::optional<double> predicted, remeasured, oracle, abs_error;
};

/// Two truth generators planted together (EvalOptions::pairs; or one alone, second "none"), over the scoring seeds.
/// The set scores treat each log's added effects as a set against its truth effects (precision: added effects that
/// are true; recall: true effects added; F1: their harmonic mean), pooled over the logs.
struct PairScore {
    std::string first, second;                ///< truth generators (second "none": the first alone)
    std::string first_effect, second_effect;  ///< the library effects they stand for ("" for none)
    double level = 0.0;                       ///< each at this multiple of its own a_50
    int logs = 0, detected = 0;
    int verdict_one = 0;    ///< the verdict (the first effect added) is a truth effect
    int all = 0;            ///< every truth effect added
    int wrong = 0;          ///< an effect added that neither generator stands for
    int unexplained = 0;    ///< verdict `unexplained`
    int added = 0;          ///< effects added, over the logs
    int found = 0;          ///< true effects added, over the logs (at most 2 per log)
    int truths = 0;         ///< truth effects planted, over the logs
    int found_or_pair = 0;  ///< true effects added or declared as an added effect's close call
    /// Effects added with the held-out score already within its bound (Explanation::within_bound_before()), and how
    /// many of them a truth stands for: how far such a step is to be trusted, beside `added` and `found` for all.
    int within_bound_added = 0, within_bound_true = 0;
    double precision = 0.0, recall = 0.0, f1 = 0.0, recall_or_pair = 0.0;
    /// Median held-out shrink, (before - after) / (before - 1), of the final model on the logs given every truth
    /// effect.
    std::optional<double> shrink;
};

/// One of the benchmark's targets read on the scoring cases: a rate with its 95 % Clopper-Pearson interval.
struct TargetScore {
    std::string target;  ///< what is counted, e.g. "top-1: kasdin_flicker -> flicker at 2 x a_50"
    std::size_t count = 0, logs = 0;
    double rate = 0.0, low = 0.0, high = 1.0;
    double bound = 0.0;  ///< the target: rate <= bound when `at_most`, else rate >= bound
    bool at_most = false;
    bool met = false;      ///< by the estimate
    bool settled = false;  ///< the interval lies wholly on one side of the bound
};

/// The level at which attribution is judged: twice each effect's detection threshold.
inline constexpr double kTargetLevel = 2.0;

struct EvalScores {
    EvalOptions options;
    Thresholds thresholds;
    std::vector<DetectionSize> sizes;
    std::size_t clean = 0, clean_flagged = 0;  ///< clean scoring logs and those given a verdict other than none
    double fpr_low = 0.0, fpr_high = 0.0;      ///< 95 % Clopper-Pearson interval of the false-positive rate
    std::vector<std::string> verdicts;         ///< the confusion matrix's columns
    /// Per truth generator ("none" first): its library effect and the count of each verdict, all sizes.
    std::vector<std::pair<std::string, std::map<std::string, int>>> confusion;
    std::vector<SizeScore> by_size;
    /// False-positive rate <= 5 %; at kTargetLevel, top-1 >= 80 % per library effect and out-of-library logs
    /// attributed to a library effect <= 20 % (also over all sizes). Rows without logs are left out.
    std::vector<TargetScore> targets;
    std::vector<PairScore> pairs;  ///< two-effect logs, per pair
};

/// Scores the scoring cases under `th`.
EvalScores score(const std::vector<EvalCase>& cases, const Thresholds& th, const EvalOptions& options,
                 const std::vector<DetectionSize>& sizes, const std::vector<PairCase>& pairs = {});

}  // namespace driftlab::host::gap
