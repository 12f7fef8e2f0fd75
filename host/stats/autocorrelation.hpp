// Biased sample autocovariance (paper eq. 3) and the integrated autocorrelation time derived from it.
// docs/analysis.md §3.
#pragma once

#include <cstddef>
#include <vector>

namespace driftlab::host::stats {

/// R(d) = (1/N) sum_{k=0}^{N-1-d} w(k) w(k+d) for d = 0..max_lag (eq. 3; the mean is NOT removed, as in the
/// paper: a fit residual has mean zero already). max_lag is clipped to N-1. O(N log N) by FFT.
std::vector<double> biased_autocovariance(const std::vector<double>& w, std::size_t max_lag);

/// Integrated autocorrelation time tau = 1 + 2 sum_{d=1}^{W} rho(d) with Sokal's automatic window (the
/// smallest W with W >= c tau(W), c = 5), from a normalised autocorrelation rho (rho[0] = 1). The variance
/// of a mean, and of slowly varying regression coefficients, is tau times its white-noise value. Never < 1.
struct AutocorrelationTime {
    double tau = 1.0;
    std::size_t window = 0;    ///< W, lags summed
    bool window_found = true;  ///< false when rho ran out before W >= c tau (tau is then a lower bound)
};
AutocorrelationTime integrated_autocorrelation_time(const std::vector<double>& rho, double c = 5.0);

}  // namespace driftlab::host::stats
