// One deviation on a tau grid with noise type, EDF and confidence interval per tau (docs/allan.md §§3-5): what
// `driftlab allan` reports, minus the term fit.
#pragma once

#include <vector>

#include "host/stats/deviation.hpp"
#include "host/stats/edf.hpp"
#include "host/stats/phase_record.hpp"
#include "host/stats/tau_grid.hpp"

namespace driftlab::host::stats {

/// A deviation curve with its uncertainty. Arrays run parallel to `curve.m`.
struct AnalysedCurve {
    DeviationCurve curve;
    std::vector<int> alpha;              ///< noise type used for the EDF (see noise_id.hpp)
    std::vector<bool> alpha_identified;  ///< false: too few points at this tau, alpha carried from a shorter tau
    std::vector<double> edf;             ///< equivalent degrees of freedom
    std::vector<double> ci_low;          ///< lower confidence bound of the deviation [data unit]
    std::vector<double> ci_high;         ///< upper confidence bound [data unit]
};

/// Averaging factors for `type` on `record`: the grid up to Stable32's largest factor for that statistic.
std::vector<std::int64_t> analysis_factors(const PhaseRecord& record, Deviation type, const TauGridOptions& grid);

/// Evaluates `type` on the factors, identifies the noise per tau by lag-1 autocorrelation (on the longest
/// gap-free segment), and derives EDF (Greenhall-Riley) and the chi-square interval at `confidence`.
/// With gaps, each segment's EDF is computed for its own length and the segments are pooled as independent
/// estimates weighted by their term counts. The factors are shared among `threads` threads (the same digits).
AnalysedCurve analyse_deviation(const PhaseRecord& record, Deviation type, std::span<const std::int64_t> ms,
                                double confidence = kOneSigmaConfidence, int threads = 1);

}  // namespace driftlab::host::stats
