// Special functions for the intervals and tests of the analysis (docs/analysis.md §4):
// regularized incomplete gamma and beta, Student t and chi-square tails and quantiles.
// Series and continued fractions after Numerical Recipes (3rd ed., §6.2 and §6.4) with modified Lentz;
// relative accuracy about 1e-13 over the ranges the tools use (degrees of freedom 1..1e8).
#pragma once

namespace driftlab::host {

/// Regularized lower incomplete gamma P(a, x) = gamma(a, x) / Gamma(a); a > 0, x >= 0.
double regularized_gamma_p(double a, double x);
/// Regularized upper incomplete gamma Q(a, x) = 1 - P(a, x), computed without cancellation.
double regularized_gamma_q(double a, double x);
/// Regularized incomplete beta I_x(a, b); a, b > 0, 0 <= x <= 1.
double regularized_beta(double a, double b, double x);

/// P(X > x) for X ~ chi-square with `dof` degrees of freedom.
double chi_square_survival(double x, double dof);
/// P(T <= t) for T ~ Student t with `dof` degrees of freedom (dof may be fractional).
double student_t_cdf(double t, double dof);
/// The p-quantile of Student t with `dof` degrees of freedom, 0 < p < 1.
double student_t_quantile(double p, double dof);

}  // namespace driftlab::host
