// The stable JSON of `driftlab gap --json`; keys documented in docs/gap.md §JSON.
#pragma once

#include <nlohmann/json.hpp>

#include "host/gap/diagnose.hpp"

namespace driftlab::host::gap {

/// verdict, explanations, located, located_after, gap_before, gap_after, not_identifiable, not_tried,
/// calibration, timing, replicates, threshold_z.
nlohmann::json gap_to_json(const GapResult& result, int replicates);

}  // namespace driftlab::host::gap
