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
    std::vector<TimeWindow> excluded;                           ///< and outside each of these (--exclude)
    FitOptions fit;
    stats::WhitenessOptions whiteness;
};

/// Fewest samples the analysis accepts in the selected range.
inline constexpr std::size_t kMinAnalysisSamples = 20;

struct DriftAnalysis {
    Series data;                   ///< the samples analysed (after the time restriction)
    double sample_period_s = 0.0;  ///< median spacing [s]
    std::size_t time_gaps = 0;     ///< spacings above 1.5x the median
    FitResult fit;
    stats::WhitenessResult whiteness;
    ParameterIntervals plain;    ///< assuming white residuals
    ParameterIntervals widened;  ///< with the residual's autocorrelation time (= plain when white)
    std::vector<std::string> warnings;
    bool t_beyond_record = false;   ///< T above 3x the record's end, or no curvature seen: only C1/T is determined
    bool t_below_sampling = false;  ///< T below the sampling interval: the transient is not resolved

    /// Whether the data determine C1 and T: not for a singular fit, nor where T is beyond the record (only their
    /// ratio, plain.initial_slope). The fit's values are then arbitrary (gyro C1 = -6.9e11 counts on a warm log).
    bool c1_and_t_determined() const { return fit.status != FitStatus::singular && !t_beyond_record; }
    /// Whether they determine C2: not for a singular fit, unless T is beyond the record, where eq. 1 is a straight
    /// line over the record and C2 its start.
    bool c2_determined() const { return fit.status != FitStatus::singular || t_beyond_record; }
    /// Why a parameter is not determined ("" when all are), for the line under a table that prints "not determined".
    std::string undetermined_reason() const;
};

/// What `fit` and `report` show in place of a parameter the data do not determine (DriftAnalysis::c1_and_t_determined).
inline constexpr const char* kNotDetermined = "not determined";

/// Whether a time constant is too long for a record ending at `record_end_s` [s since power-on] to tell an
/// exponential's size from its time constant: it is then nearly a straight slope over the record, of which only the
/// ratio (the initial slope) is seen. Eq. 1's T here, and the gap diagnosis's second time constant.
constexpr bool beyond_record(double time_constant_s, double record_end_s) {
    return time_constant_s > 3.0 * record_end_s;
}

/// Runs the analysis. Throws DataError (naming the file and series) when fewer than kMinAnalysisSamples
/// samples are in range or the series is constant.
DriftAnalysis analyse_drift(const Series& series, const AnalysisOptions& options = {});

}  // namespace driftlab::host::fit
