// The per-channel analysis behind `driftlab fit`, `whiteness` and `report`: restrict the time range, fit
// eq. 1, test the residual for whiteness (eqs. 2–4) and widen the intervals when it is coloured.
// docs/analysis.md §1–3.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "host/fit/intervals.hpp"
#include "host/fit/lm_fit.hpp"
#include "host/fit/series.hpp"
#include "host/stats/whiteness.hpp"

namespace driftlab::host::fit {

struct AnalysisOptions {
    double t_min_s = -std::numeric_limits<double>::infinity();  ///< keep samples with t_s >= t_min_s
    double t_max_s = std::numeric_limits<double>::infinity();   ///< and t_s <= t_max_s
    FitOptions fit;
    stats::WhitenessOptions whiteness;
};

/// Fewest samples the analysis accepts in the selected range.
inline constexpr std::size_t kMinAnalysisSamples = 20;

struct DriftAnalysis {
    Series data;                      ///< the samples analysed (after the time restriction)
    double sample_period_s = 0.0;     ///< median spacing [s]
    std::size_t time_gaps = 0;        ///< spacings above 1.5x the median
    FitResult fit;
    stats::WhitenessResult whiteness;
    ParameterIntervals plain;         ///< assuming white residuals
    ParameterIntervals widened;       ///< with the residual's autocorrelation time (= plain when white)
    std::vector<std::string> warnings;
};

/// Runs the analysis. Throws DataError (naming the file and series) when fewer than kMinAnalysisSamples
/// samples are in range or the series is constant.
DriftAnalysis analyse_drift(const Series& series, const AnalysisOptions& options = {});

}  // namespace driftlab::host::fit
