// JSON of the drift fit and whiteness results; the stable keys are listed in docs/analysis.md §5.
#pragma once

#include <nlohmann/json.hpp>

#include "host/fit/drift_analysis.hpp"
#include "host/stats/whiteness.hpp"

namespace driftlab::host::report {

/// {fraction_inside, ljung_box_p, white, ...}; with `arrays` also the lags (at w.sample_period_s) and autocorrelations.
nlohmann::json whiteness_json(const stats::WhitenessResult& w, bool arrays);

/// One channel of `driftlab fit --json`: C1, C2, T ({value, stderr, ci95, ci95_widened}), physical units,
/// status, n, rms, whiteness, warnings.
nlohmann::json fit_json(const fit::DriftAnalysis& a);

}  // namespace driftlab::host::report
