// Variable-projection fits of the deterministic candidates jointly with eq. 1 on the fitting part of a log:
// for fixed time constants/period the amplitudes are linear least squares; the nonlinear ones come from a log
// grid refined by Nelder-Mead. docs/gap.md §Candidates.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Dense>

namespace driftlab::host::gap {

/// y = C1 (1 - e^{-t/T}) + C3 (1 - e^{-t/T2}) + C2, with T2 >= 2 T (E1 on top of eq. 1; closer time constants are one
/// exponential's derivative, fitted with huge opposite amplitudes).
struct TwoExponentials {
    double c1_counts = 0.0, c2_counts = 0.0, t_s = 1.0;
    double c3_counts = 0.0, t2_s = 1.0;
    double rss = 0.0;
};

/// y = C1 (1 - e^{-t/T}) + C2 + A sin(2 pi t / P + phi) (E2 on top of eq. 1), P between 8 samples and half the span.
struct ExponentialAndSine {
    double c1_counts = 0.0, c2_counts = 0.0, t_s = 1.0;
    double amplitude_counts = 0.0, period_s = 1.0, phase_rad = 0.0;
    double rss = 0.0;
};

/// The residual of y = C1 (1 - e^{-t/T}) + C2 + S1 [k >= cut1] + S2 [k >= cut2] (eq. 1 with two level steps at given
/// sample indices) over all of (t_s, y), T profiled over a log grid from 0.003 to about 27 spans (ratio 1.2): the
/// level-step test's steps with eq. 1 fitted again beside them.
std::vector<double> eq1_and_steps_residual(const std::vector<double>& t_s, const std::vector<double>& y,
                                           std::size_t cut1, std::size_t cut2);

/// The directions in which a least-squares fit of eq. 1 with time constant T moves the mean: 1, e^{-t/T} and
/// (t/T) e^{-t/T} (its derivative in T), one row per sample. What such a fit absorbs of the noise lies in their span
/// (AbsorbedColumns, whittle.hpp).
Eigen::MatrixXd eq1_tangent(const std::vector<double>& t_s, double tau_s);

/// An orthonormal basis of eq1_tangent()'s span: what a residual loses when eq. 1 is refitted beside another fit.
Eigen::MatrixXd eq1_tangent_basis(const std::vector<double>& t_s, double tau_s);

/// Fits the first `n` samples of (t_s, y).
TwoExponentials fit_two_exponentials(const std::vector<double>& t_s, const std::vector<double>& y, std::size_t n);
ExponentialAndSine fit_exponential_and_sine(const std::vector<double>& t_s, const std::vector<double>& y,
                                            std::size_t n);

}  // namespace driftlab::host::gap
