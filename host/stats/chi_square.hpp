// Chi-square distribution for confidence intervals on variances (docs/allan.md §4): the regularized lower
// incomplete gamma function P(a, x) and its inverse, for any real degrees of freedom > 0 (EDFs are fractional).
#pragma once

namespace driftlab::host::stats {

/// Regularized lower incomplete gamma P(a, x) = gamma(a, x) / Gamma(a), a > 0, x >= 0. Series for x < a + 1,
/// Lentz continued fraction for Q = 1 - P otherwise; accurate to a few ulps times the number of terms.
double regularized_gamma_p(double a, double x);

/// Regularized upper incomplete gamma Q(a, x) = 1 - P(a, x), computed directly where it is small.
double regularized_gamma_q(double a, double x);

/// Chi-square CDF with `dof` degrees of freedom: P(dof/2, x/2).
double chi_square_cdf(double x, double dof);

/// Chi-square quantile: the x with chi_square_cdf(x, dof) = p, 0 < p < 1, dof > 0. Newton steps
/// from a Wilson-Hilferty start, safeguarded by a bisection bracket; relative accuracy about 1e-12.
/// Throws std::invalid_argument outside the domain.
double chi_square_quantile(double p, double dof);

}  // namespace driftlab::host::stats
