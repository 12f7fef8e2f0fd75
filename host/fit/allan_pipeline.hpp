// What `driftlab allan` does to one series (docs/allan.md §7): place it on the tau0 grid with explicit gaps,
// optionally remove the fitted turn-on drift (paper eq. 1, host/fit), and evaluate the requested deviations with
// noise type, EDF and confidence intervals, plus the IEEE 952 terms fitted to the overlapping ADEV.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "host/fit/drift_model.hpp"
#include "host/fit/lm_fit.hpp"
#include "host/stats/allan_analysis.hpp"
#include "host/stats/noise_terms.hpp"
#include "host/stats/rate_unit.hpp"

namespace driftlab::host::fit {

struct AllanRequest {
    stats::InputKind kind = stats::InputKind::rate;
    stats::TauGridOptions grid;
    std::vector<stats::Deviation> deviations = {
        stats::Deviation::oadev};  ///< oadev is always evaluated (the terms need it)
    bool remove_drift = true;      ///< fit eq. 1 and also analyse the residual (rate input only)
    /// drift_not_fitted when remove_drift is false: the caller's reason
    std::string kept_drift_status = "not requested";
    FitOptions drift_fit;  ///< the eq. 1 fit's options
    double confidence = stats::kOneSigmaConfidence;
    int threads = 1;  ///< the averaging factors are shared among them (the same digits however many)
};

/// The curves of one version of the series (raw or drift-removed); `curves` in request order, oadev first.
struct AllanCurves {
    std::vector<stats::AnalysedCurve> curves;
    stats::NoiseTermFit terms;  ///< fitted to the oadev curve
    const stats::AnalysedCurve* find(stats::Deviation d) const;
};

struct AllanResult {
    double tau0_s = 0.0;
    std::size_t samples = 0;            ///< grid slots (input samples plus gap slots)
    std::size_t gap_samples = 0;        ///< slots that are gaps (missing, NaN)
    std::size_t packed_samples = 0;     ///< samples placed 2 or more slots after their time (see UniformSeries)
    std::size_t packed_most_slots = 0;  ///< the largest such displacement [slots]
    double longest_gap_free_s = 0.0;    ///< time the longest gap-free stretch of the grid spans: no term is longer
    AllanCurves raw;
    std::optional<AllanCurves> drift_removed;   ///< set when the drift was fitted and removed
    std::optional<DriftParameters> drift;       ///< the eq. 1 fit used [counts, s]
    std::optional<FitStatus> drift_fit_status;  ///< the eq. 1 fit's status, when it ran
    std::string drift_not_fitted;               ///< else why not (not requested, phase input, the fit's error)
    /// JSON's drift_status: the fit's status as fit --json spells it (iteration_limit), else drift_not_fitted.
    std::string drift_status_name() const;
    /// The same for a terminal, in the words of fit's table (fit_status_words: "not converged (iteration limit)").
    std::string drift_status_words() const;
    /// The curves the result is read from: drift removed when it was, else raw.
    const AllanCurves& primary() const { return drift_removed ? *drift_removed : raw; }
};

/// One series' Allan analysis as `allan` shows it: the result with the sample period it was computed at, the time span
/// of the rows kept, the unit of its samples, and what to warn of (rows packed onto the grid, a few lone values).
struct AllanSeriesResult {
    std::string name;
    double tau0_s = 0.0;
    double t_first_s = 0.0, t_last_s = 0.0;
    AllanResult result;
    stats::SampleUnit unit;
    std::optional<std::string> packing_warning, lone_values_warning;
};

/// Analyses samples `values` taken at times `t_s` [s] (strictly increasing) on a grid of `tau0_s`.
AllanResult analyse_allan(const std::vector<double>& t_s, const std::vector<double>& values, double tau0_s,
                          const AllanRequest& request);

/// The caveat of samples packed onto the grid (rows faster than tau0), when it can bias `curve` (one of `r`'s):
/// packing keeps the samples' order and moves each at most packed_most_slots x tau0 late. White noise does not care
/// when a sample was taken, and it is what the curve reads left of its minimum; from the minimum on (bias
/// instability, rate random walk, drift) it reads correlated noise, for which a displacement d changes an averaging
/// time tau by up to d / tau. Up to kSpacingTolerance of the minimum's tau that is no more than tau0 itself may be
/// off (period_agrees), and nothing is said: a steady burst reader (the MPU6050 recording's gyro: 0.55 s against a
/// minimum at 82 s) stays below, a record that changes its rate part-way (every later row moved by what the fast
/// stretch gained) does not. Nothing either without packing or without a curve.
std::optional<std::string> packing_caveat(const AllanResult& r, const stats::AnalysedCurve& curve);

/// The one place the turn-on drift enters the Allan analysis: fits eq. 1 to (t_s, values) and sets `out`'s drift
/// (none when the fit fails or does not converge), drift_fit_status and, for a fit that threw, drift_not_fitted.
void fit_turn_on_drift(const std::vector<double>& t_s, const std::vector<double>& values, const FitOptions& options,
                       AllanResult& out);

}  // namespace driftlab::host::fit
