// Ljung–Box portmanteau test of whiteness (Ljung & Box, Biometrika 65(2), 1978). docs/analysis.md §3.
#pragma once

#include <cstddef>
#include <vector>

namespace driftlab::host::stats {

struct LjungBoxResult {
    double statistic = 0.0;  ///< Q = n (n + 2) sum_{k=1}^{h} rho_k^2 / (n - k)
    std::size_t lags = 0;    ///< h
    double dof = 0.0;        ///< chi-square degrees of freedom, h - fitted_dof
    double p_value = 1.0;    ///< P(chi2(dof) > Q): small means "not white"
};

/// Q from the normalised autocorrelation `rho` (rho[0] = 1, at least `lags` + 1 values) of n samples.
/// `fitted_dof` is subtracted from h (ARMA parameters; 0 for a regression residual).
LjungBoxResult ljung_box(const std::vector<double>& rho, std::size_t n, std::size_t lags, std::size_t fitted_dof = 0);

/// The usual lag count: min(20, n / 5), at least 1.
std::size_t default_ljung_box_lags(std::size_t n);

}  // namespace driftlab::host::stats
