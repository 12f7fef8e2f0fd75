// Whiteness of a fit residual: the paper's ensemble autocorrelation test (eqs. 2–4, Fig. 4), a Ljung–Box
// test on the whole residual, and the integrated autocorrelation time used to widen intervals.
// docs/analysis.md §3.
//
// Ensemble (paper): M sequences of L seconds each; per sequence the biased autocovariance R(d) (eq. 3),
// normalised by R(0); the M curves are averaged. For white noise each normalised value has standard error
// 1/sqrt(L_samples) (eq. 4), so the average has 1/sqrt(M L_samples) and the +-2 sigma bounds are
// +-2/sqrt(M L_samples). The sequences are spread evenly over the record without overlap.
// Verdict: "white" when the Ljung–Box p-value is at least alpha. The fraction of lags inside the bounds is
// the paper's figure of merit; it is reported, not used for the verdict, because over all lags of short
// sequences it exceeds 95.5 % even for white noise (the biased estimate shrinks at large lags).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "host/stats/autocorrelation.hpp"
#include "host/stats/ljung_box.hpp"

namespace driftlab::host::stats {

struct WhitenessOptions {
    std::size_t sequences = 10;       ///< M (paper: 10)
    double sequence_length_s = 50.0;  ///< L [s] (paper: 50 s)
    std::size_t ljung_box_lags = 0;   ///< h; 0 = min(20, n/5)
    double alpha = 0.05;              ///< test size of the verdict
};

struct WhitenessResult {
    double sample_period_s = 0.0;  ///< [s] the spacing the lags count (the caller's sample period)
    // The paper's ensemble test.
    std::size_t sequences_used = 0;    ///< M actually used
    std::size_t sequence_samples = 0;  ///< samples per sequence
    double sequence_length_s = 0.0;    ///< [s] actually used
    std::vector<double> ensemble_rho;  ///< averaged normalised autocorrelation, lags 0..sequence_samples-1
    double bound = 0.0;                ///< +-2 sigma bound on ensemble_rho, 2/sqrt(M L_samples)
    double fraction_inside = 0.0;      ///< of lags 1..sequence_samples-1
    std::string adaptation;            ///< what was changed because the residual is short ("" = none)
    // Whole residual.
    std::vector<double> rho;  ///< normalised autocorrelation, lags 0..max(h, autocorrelation window)
    LjungBoxResult ljung_box;
    AutocorrelationTime autocorrelation_time;
    bool white = true;  ///< ljung_box.p_value >= alpha
};

/// Runs the tests on `residual` sampled every `sample_period_s` seconds (> 0). Throws UsageError when the
/// residual has fewer than 10 samples or zero variance (callers check their data first and say where).
WhitenessResult test_whiteness(const std::vector<double>& residual, double sample_period_s,
                               const WhitenessOptions& options = {});

}  // namespace driftlab::host::stats
