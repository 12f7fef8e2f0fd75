// The views of a withheld-effect benchmark run (`driftlab gap-eval`): the markdown tables of docs/gap-results.md, the
// JSON of --json, and the plots of --plot DIR. docs/gap.md §Evaluation.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "host/gap_eval/eval_scores.hpp"

namespace driftlab::host::view {

/// The markdown tables of docs/gap-results.md.
std::string scores_markdown(const gap::EvalScores& scores);

/// The same as JSON: keys `thresholds`, `tune_seeds`, `score_seeds`, `samples`, `replicates`, `a50[]`
/// (`generator`, `a50`, `curve[]` {`size`, `detected`, `logs`}), `false_positive` {`clean`, `flagged`, `rate`,
/// `interval`}, `confusion` {generator: {verdict: count}}, `by_size[]` (`generator`, `truth`, `level`, `logs`,
/// `detected`, `top1`, `or_pair`, `shrink` {`predicted`, `remeasured`, `oracle`, `abs_error`}), `targets[]` (`target`,
/// `count`, `logs`, `rate`, `interval`, `bound`, `at_most`, `met`, `settled`), `pairs[]` (`generators`, `effects`,
/// `level`, `logs`, `detected`, `verdict_one`, `all`, `wrong`, `unexplained`, `added`, `found`, `truths`,
/// `found_or_pair`, `within_bound_added`, `within_bound_true`, `precision`, `recall`, `recall_or_pair`, `f1`,
/// `shrink`).
nlohmann::json scores_json(const gap::EvalScores& scores);

/// Per truth generator, the share of scoring logs detected and the share given the right verdict against the effect's
/// size in multiples of its detection threshold a_50, each with its exact 95 % interval: writes DIR/gap_eval_detected
/// and DIR/gap_eval_top1 (.png and .svg, with their .dat and .gp); returns the image paths. Throws Error when gnuplot
/// is missing, UsageError when the run planted nothing (no sizes to plot).
std::vector<std::string> write_eval_plots(const gap::EvalScores& scores, const std::string& dir);

}  // namespace driftlab::host::view
