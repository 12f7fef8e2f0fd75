// How repeatable is a verdict? A parametric bootstrap of the diagnosis: logs simulated from the estimated model (the
// added effects estimated on the whole log, as --model-out writes it) on the real log's instants (the same channels,
// smoothing and raw codes), each diagnosed exactly as the log was. The share of them that gets the log's verdict
// says how often the model the log was read as would be read the same way again: near 1 for a clear shape, lower
// where noise processes are a close call. It is repeatability under the fitted model, not the chance of being right
// (a wrong flicker reading of a Gauss-Markov log repeats well: flicker's own logs read as flicker).
// Its words are in host/view/gap_phrases.hpp; docs/gap.md §Verdict stability.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "host/gap/diagnose.hpp"

namespace driftlab::host::gap {

/// One estimated parameter of an added effect against its estimates on the simulated logs that added the same effect
/// on the same channel: where the estimator scatters, and where it centres, when the estimated model is the truth
/// (a parametric bootstrap of the estimate, conditional on the effect being found again).
struct ParameterSpread {
    std::string effect, channel, param;
    double estimate = 0.0;       ///< the log's own value (estimated on the whole log)
    std::vector<double> values;  ///< the simulated logs' values, sorted
    std::size_t logs_added = 0;  ///< simulated logs that added the effect on the channel again (a DNL table's codes
                                 ///< can differ from log to log, so a parameter may have fewer values)
    double quantile(double q) const;  ///< linear between order statistics; NaN without values
};

struct VerdictStability {
    std::size_t logs = 0;                         ///< simulated logs diagnosed
    std::map<std::string, std::size_t> verdicts;  ///< their verdicts, counted
    std::size_t same = 0;                         ///< how many got the log's own verdict
    std::vector<ParameterSpread> params;          ///< per parameter of each added effect, in the explanation's order
};

/// Diagnoses `logs` logs simulated from `result.whole_log_model` (the unit as the diagnosis of `log` on `unit` under
/// `options` estimates it, the model `--model-out` writes).
/// Log b is simulated with its own seed (from options.seed and b) and diagnosed with options unchanged, so that
/// the run repeats exactly; options.progress is told each log as it starts.
VerdictStability verdict_stability(const GapResult& result, const LogData& log, const sim::SimModel& unit,
                                   const GapOptions& options, std::size_t logs);

}  // namespace driftlab::host::gap
