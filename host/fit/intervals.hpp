// Standard errors and 95 % intervals of the eq. 1 parameters, plain and widened for coloured residuals.
// docs/analysis.md §2.3.
//
// Plain: cov = s^2 (J^T J)^-1 with s^2 = RSS / (n - 3), intervals value +- t_{0.975, n-3} se (as
// scipy's curve_fit and Numerical Recipes); for T the interval is symmetric in log T (T exp(+-t se/T)),
// because T is positive and its estimate right-skewed. These assume white residuals. When the residual is
// correlated with integrated autocorrelation time tau (autocorrelation.hpp), the variance of a smooth
// regression coefficient grows by about tau, so the widened intervals use se sqrt(tau) and
// t_{0.975, n/tau - 3}: the effective sample size is n / tau.
#pragma once

#include <array>
#include <string>

#include "host/fit/lm_fit.hpp"

namespace driftlab::host::fit {

struct Estimate {
    double value = 0.0;
    double stderr_ = 0.0;          ///< standard error (trailing _ because `stderr` is a macro)
    std::array<double, 2> ci95{};  ///< [lo, hi]
};

/// "value +- stderr" to the precision of the error; "value (no interval: the fit is singular)" when the error is not
/// finite. For sentences and the text output.
std::string with_error(const Estimate& e);

struct ParameterIntervals {
    Estimate c1, c2, t_s;  ///< in the data's unit; T in seconds
    /// C1/T, the drift rate at power-on [data unit / s] (delta method over the covariance of C1 and T): what a
    /// record much shorter than T determines where C1 and T are not separately determined.
    Estimate initial_slope;
    double dof = 0.0;         ///< degrees of freedom of the t quantile
    double t_quantile = 0.0;  ///< t_{0.975, dof}
    double inflation = 1.0;   ///< factor applied to the standard errors (sqrt(tau))
};

/// Intervals from a fit. `tau` >= 1 is the integrated autocorrelation time of the residual (1 = white).
/// Needs n / tau > 3; otherwise the intervals are infinite.
ParameterIntervals parameter_intervals(const FitResult& fit, double tau = 1.0);

}  // namespace driftlab::host::fit
