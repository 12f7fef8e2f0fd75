// Chi-square distribution for confidence intervals on variances (docs/allan.md §4): CDF and quantile for any
// real degrees of freedom > 0 (EDFs are fractional), on the incomplete gamma of host/util/special_functions.
#pragma once

namespace driftlab::host::stats {

/// Chi-square CDF with `dof` degrees of freedom: P(dof/2, x/2).
double chi_square_cdf(double x, double dof);

/// Chi-square quantile: the x with chi_square_cdf(x, dof) = p, 0 < p < 1, dof > 0. Newton steps
/// from a Wilson-Hilferty start, safeguarded by a bisection bracket; relative accuracy about 1e-12.
/// Throws std::invalid_argument outside the domain.
double chi_square_quantile(double p, double dof);

}  // namespace driftlab::host::stats
