// The views of the eq. 1 residual's whiteness (`driftlab whiteness`, paper eqs. 2-4 and Fig. 4): the table of the
// ensemble autocorrelation's share inside its bounds and the Ljung-Box test, the JSON (docs/analysis.md §5), Fig. 4.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "host/fit/file_analysis.hpp"
#include "host/stats/whiteness.hpp"

namespace driftlab::host::view {

/// The terminal's table, one row per series.
void print_whiteness_table(const fit::FileAnalysis& file);

/// {fraction_inside, ljung_box_p, white, ...}; with `arrays` also the lags (at w.sample_period_s) and autocorrelations.
nlohmann::json whiteness_json(const stats::WhitenessResult& w, bool arrays);

/// `driftlab whiteness --json`: {file, channels: {name: {whiteness (with arrays), warnings} or {error}}}.
nlohmann::json whiteness_to_json(const fit::FileAnalysis& file);

/// Fig. 4 of every analysed series as PNG and SVG in `dir`.
void write_whiteness_plots(const fit::FileAnalysis& file, const std::string& dir);

}  // namespace driftlab::host::view
