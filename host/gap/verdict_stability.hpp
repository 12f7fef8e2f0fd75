// How repeatable is a verdict? A parametric bootstrap of the diagnosis: logs simulated from the estimated model (the
// added effects estimated on the whole log, as --model-out writes it) on the real log's instants (the same channels,
// smoothing and raw codes), each diagnosed exactly as the log was. The share of them that gets the log's verdict
// says how often the model the log was read as would be read the same way again: near 1 for a clear shape, lower
// where noise processes are a close call. It is repeatability under the fitted model, not the chance of being right
// (a wrong flicker reading of a Gauss-Markov log repeats well: flicker's own logs read as flicker).
// docs/gap.md §Verdict stability.
#pragma once

#include <cstddef>
#include <map>
#include <string>

#include "host/gap/diagnose.hpp"

namespace driftlab::host::gap {

struct VerdictStability {
    std::size_t logs = 0;                           ///< simulated logs diagnosed
    std::map<std::string, std::size_t> verdicts;    ///< their verdicts, counted
    std::size_t same = 0;                           ///< how many got the log's own verdict
};

/// Diagnoses `logs` logs simulated from `result.whole_log_model` (the unit as the diagnosis of `log` on `unit` under
/// `options` estimates it, the model `--model-out` writes).
/// Log b is simulated with its own seed (from options.seed and b) and diagnosed with options unchanged, so that
/// the run repeats exactly; options.progress is told each log as it starts.
VerdictStability verdict_stability(const GapResult& result, const LogData& log, const sim::SimModel& unit, const GapOptions& options,
                                   std::size_t logs);

/// The result in words the terminal and the report share: "of N logs ... k (p %) are called V; v1 n1 v2 n2".
std::string stability_sentence(const VerdictStability& stability, const std::string& verdict);

}  // namespace driftlab::host::gap
