// Chi-square distribution for confidence intervals on variances (docs/allan.md §4): CDF and quantile for any
// real degrees of freedom > 0 (EDFs are fractional), from Boost.Math's chi_squared distribution.
#pragma once

namespace driftlab::host::stats {

/// Chi-square CDF with `dof` degrees of freedom: P(dof/2, x/2).
double chi_square_cdf(double x, double dof);

/// P(X > x) for X ~ chi-square with `dof` degrees of freedom, without the cancellation of 1 - cdf.
double chi_square_survival(double x, double dof);

/// Chi-square quantile: the x with chi_square_cdf(x, dof) = p, 0 < p < 1, dof > 0.
/// Throws std::invalid_argument outside the domain.
double chi_square_quantile(double p, double dof);

}  // namespace driftlab::host::stats
