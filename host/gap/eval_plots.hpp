// Plots of a withheld-effect benchmark run (`driftlab gap-eval --plot DIR`): per truth generator, the share of
// scoring logs detected and the share given the right verdict against the effect's size in multiples of its
// detection threshold a_50, each with its exact 95 % interval. docs/gap.md §Evaluation.
#pragma once

#include <string>
#include <vector>

#include "host/gap/eval_scores.hpp"

namespace driftlab::host::gap {

/// Writes DIR/gap_eval_detected and DIR/gap_eval_top1 (.png and .svg, with their .dat and .gp); returns the image
/// paths. Throws Error when gnuplot is missing, UsageError when the run planted nothing (no sizes to plot).
std::vector<std::string> write_eval_plots(const EvalScores& scores, const std::string& dir);

}  // namespace driftlab::host::gap
