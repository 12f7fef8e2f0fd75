// The stable JSON of `driftlab gap --json`; keys documented in docs/gap.md §JSON.
#pragma once

#include <nlohmann/json.hpp>

#include "host/gap/diagnose.hpp"
#include "host/gap/verdict_stability.hpp"

namespace driftlab::host::gap {

/// verdict, explanations, located, located_after, gap_before, gap_after, not_identifiable, not_tried,
/// calibration, timing, replicates, holdout, fit_fraction, threshold_z, cells, of a diagnosis run with `options`.
nlohmann::json gap_to_json(const GapResult& result, const GapOptions& options);

/// --stability's result: logs, verdicts, same (a share), params[] {effect, channel, param, estimate, values (sorted),
/// median, p16, p84; null medians where no log added the effect again}.
nlohmann::json stability_to_json(const VerdictStability& stability);

}  // namespace driftlab::host::gap
