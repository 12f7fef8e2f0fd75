// The stable JSON of `driftlab gap --json`; keys documented in docs/gap.md §JSON.
#pragma once

#include <array>

#include <nlohmann/json.hpp>

#include "host/gap/diagnose.hpp"
#include "host/gap/verdict_stability.hpp"

namespace driftlab::host::gap {

/// The top-level keys of gap_to_json(), in the order --help lists them (a test holds the two together).
inline constexpr auto kGapJsonKeys = std::to_array<const char*>({"verdict",
                                                                 "explanations",
                                                                 "paths",
                                                                 "located",
                                                                 "located_after",
                                                                 "diffuse_gap",
                                                                 "diffuse_searched",
                                                                 "gap_before",
                                                                 "gap_after",
                                                                 "information_criterion",
                                                                 "level_steps",
                                                                 "not_identifiable",
                                                                 "not_tried",
                                                                 "constant_channels",
                                                                 "noise_free_channels",
                                                                 "saturated",
                                                                 "lone_values",
                                                                 "left_out",
                                                                 "given",
                                                                 "calibration",
                                                                 "timing",
                                                                 "replicates",
                                                                 "holdout",
                                                                 "fit_fraction",
                                                                 "max_effects",
                                                                 "threshold_z",
                                                                 "cells"});

/// The diagnosis run with `options` under the keys kGapJsonKeys (docs/gap.md §JSON).
nlohmann::json gap_to_json(const GapResult& result, const GapOptions& options);

/// --stability's result: logs, verdicts, same (a share), params[] {effect, channel, param, estimate, values (sorted),
/// median, p16, p84; null medians where no log added the effect again}.
nlohmann::json stability_to_json(const VerdictStability& stability);

}  // namespace driftlab::host::gap
