// The views of the drift fit (`driftlab fit`, and the fit in `report`): the Table 1 layout with each estimate's
// interval, the stable JSON (keys in docs/analysis.md §5) and the paper's Fig. 2-4.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "host/fit/file_analysis.hpp"

namespace driftlab::host::view {

/// The terminal's table: per series C1, C2, T, status, rms and the residual's whiteness, then each series' estimates
/// with their 95 % intervals (widened where the residual is not white).
void print_fit_table(const fit::FileAnalysis& file);

/// One channel of `driftlab fit --json`: C1, C2, T ({value, stderr, ci95, ci95_widened}), physical units,
/// status, n, rms, whiteness, warnings.
nlohmann::json fit_json(const fit::DriftAnalysis& analysis);

/// `driftlab fit --json`: {file, channels: {name: fit_json() or {error}}}.
nlohmann::json fit_to_json(const fit::FileAnalysis& file);

/// Fig. 2 (where the series has raw values), Fig. 3 and Fig. 4 of every analysed series as PNG and SVG in `dir`.
void write_fit_plots(const fit::FileAnalysis& file, const std::string& dir);

}  // namespace driftlab::host::view
