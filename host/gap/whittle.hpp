// The debiased Whittle likelihood of a residual's first differences under a model spectrum: a white floor shaped
// by the firmware's smoother, first-order Gauss-Markov components and a random walk, all sampled at the output
// instants. Differencing makes every one of them stationary (a random walk's increments are white) and removes
// the eq. 1 level the fit leaves uncertain. Only the differences inside one part of the log count (the held-out
// blocks are missing data): the model's EXPECTED periodogram of the masked series is computed exactly, so the
// gaps between interleaved blocks bias nothing (a plain periodogram of the joined blocks reads them as a random
// walk). Sykulski, Olhede, Guillaumin, Lilly & Early, "The debiased Whittle likelihood", Biometrika 106(2), 2019;
// Whittle, Ark. Mat. 2, 1953. docs/gap.md §Spectral likelihood.
#pragma once

#include <complex>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "host/gap/gap_model.hpp"

namespace driftlab::host::gap {

/// What a least-squares fit of the mean took out of the residual, as the expected periodogram needs it. The residual
/// is e = (I - P) x with P the projection onto columns X that hold the constant, so its differences are
/// d = delta - A B' delta (delta the noise's differences, A = D X (X'X)^-1, b_k(j) = sum_{s > j} X_sk); a slow
/// process loses its lowest frequencies to the fit, and a model that ignores that reads a random walk as flicker.
struct AbsorbedColumns {
    std::size_t differences = 0;                           ///< N - 1: every difference of the log
    std::vector<std::vector<std::complex<double>>> alpha;  ///< sum_t h_t A_tk e^{-i w_j t}, j = 1..(n-1)/2
    std::vector<std::vector<double>> load;                 ///< b_k, length `differences`
};

/// The differences of one part of a residual, ready for the likelihood.
struct PartPeriodogram {
    std::size_t length = 0;     ///< n: differences in the series, masked ones included (a 2-3-5 length)
    double count = 0.0;         ///< differences inside the part within the n kept (the trimmed tail is not used)
    std::vector<double> power;  ///< |sum_t m_t d_t e^{-i w_j t}|^2 / taper_energy at w_j = 2 pi j / n, j = 1..(n-1)/2
    std::vector<double> mask_overlap;         ///< sum_t m_t m_{t+tau} / taper_energy, tau = 0..n-1
    std::vector<double> taper;                ///< m_t, t = 0..n-1 (the part's mask times its taper)
    double taper_energy = 0.0;                ///< sum_t m_t^2
    std::optional<AbsorbedColumns> absorbed;  ///< the mean fit's columns, when the residual is one's
};

/// The part's periodogram: d_t = e[t+1] - e[t] where both samples lie in the part (`in_part`), 0 elsewhere; the
/// series is trimmed at its end to a length whose prime factors are 2, 3 and 5. `absorbed` (optional, one row per
/// sample, the constant in its span) are the columns a least-squares fit of the mean removed from `e`. Throws
/// std::invalid_argument when fewer than 16 differences lie in the part.
PartPeriodogram part_periodogram(const std::vector<double>& e, const std::vector<bool>& in_part,
                                 const Eigen::MatrixXd* absorbed = nullptr);

/// An orthonormal basis of x's columns (the thin Q of its QR): the same span, its projection q q', without the
/// near-collinearity of eq. 1's exponentials.
Eigen::MatrixXd orthonormal_basis(const Eigen::MatrixXd& x);

/// Autocovariance at output lags 0, 1, ... of the smoother's output for unit-variance white conversions:
/// r_m = sum_x h_x h_{x + m D}, with the LS weights h of fw::LsWindow (order 0: 1/N; order 1 evaluated at the
/// newest conversion: (6x - 2(N - 2)) / (N (N + 1)), x = 0 oldest) and D conversions per row (per output, times
/// the outputs per row).
std::vector<double> white_floor_autocovariance(const Smoothing& s);

/// The smoother output's long-run variance over its variance, (r_0 + 2 sum_{m>0} r_m) / r_0: how many outputs share
/// one output's worth of independent noise (1 when the windows do not overlap).
double white_floor_long_run_factor(const Smoothing& s);

/// A model of the output noise [counts^2], before differencing.
struct OutputSpectrum {
    double white = 0.0;  ///< variance of the conversions' white noise, shaped by the smoother
    struct Ar1 {
        double variance = 0.0;  ///< stationary variance [counts^2]
        double phi = 0.0;       ///< exp(-output period / correlation time)
    };
    std::vector<Ar1> ar1;                  ///< Gauss-Markov components (flicker is a sum of them)
    double walk_increment_variance = 0.0;  ///< random walk: variance of its step per output period [counts^2]
};

/// Autocovariance of the model's first differences at lags 0..n-1. Slow components are taken as sampled at the
/// output instants (the smoother's averaging of them matters only for correlation times near the output period,
/// where the white floor dominates): an AR(1) gives c(0) = 2v(1 - phi), c(k) = -v phi^(k-1) (1 - phi)^2.
std::vector<double> differenced_autocovariance(const OutputSpectrum& model, const std::vector<double>& floor_acov,
                                               std::size_t n);

/// C v for C the covariance of the model's first differences over v.size() consecutive lags (the Toeplitz matrix of
/// differenced_autocovariance()), in O(n) per component: the floor's few lags directly, each AR(1) by a recursion
/// each way, the walk's white increments as a multiple of v.
std::vector<double> differenced_covariance_times(const OutputSpectrum& model, const std::vector<double>& floor_acov,
                                                 const std::vector<double>& v);

/// The spectral density of the model's first differences at w_j = 2 pi j / n, j = 0..n-1 (the Fourier transform
/// of differenced_autocovariance(), in closed form: an AR(1) gives 2(1 - cos w) v (1 - phi^2) / (1 - 2 phi cos w
/// + phi^2), the walk its increment variance).
std::vector<double> differenced_density(const OutputSpectrum& model, const std::vector<double>& floor_acov,
                                        std::size_t n);

/// The expected value of `p.power` under the model: sum_tau mask_overlap(tau) c(tau) e^{-i w_j tau}, less what the
/// mean fit absorbed when `p.absorbed` is set (with C the differences' covariance, per frequency
/// -2 Re sum_k conj(alpha_k) F(C b_k) + alpha^H B'CB alpha, over the taper energy).
std::vector<double> expected_periodogram(const OutputSpectrum& model, const std::vector<double>& floor_acov,
                                         const PartPeriodogram& p);

/// expected_periodogram() of many models on one part, as a fit evaluates them. The expected periodogram is linear in
/// the covariance, so a model's is the sum of its components' (the floor's, the walk's and each AR(1)'s) at unit
/// size, weighted by their sizes: each unit component is computed once and kept (the AR(1)s by their phi, the
/// `kept` used last), and an evaluation that changes sizes only, or one Gauss-Markov component, costs one pass per
/// component instead of the FFTs of all of them. One object per thread: it is not safe to share.
class ExpectedPeriodogram {
public:
    /// Both are referenced, not copied: they must outlive the object. `kept` unit AR(1)s are kept (each is half the
    /// part's length in doubles: 1.4 MB per hour at 100 Hz); a search that moves one phi at every evaluation keeps few.
    ExpectedPeriodogram(const std::vector<double>& floor_acov, const PartPeriodogram& p, std::size_t kept = 24);
    std::vector<double> operator()(const OutputSpectrum& model);

private:
    const std::vector<double>& unit_floor();
    const std::vector<double>& unit_walk();
    const std::vector<double>& unit_ar1(double phi);

    struct Kept {
        double phi;
        std::uint64_t last_use;
        std::vector<double> values;
    };
    const std::vector<double>* floor_acov_;
    const PartPeriodogram* p_;
    std::vector<double> floor_, walk_;
    std::vector<Kept> ar1_;
    std::size_t kept_;
    std::uint64_t clock_ = 0;
};

/// Whittle negative log-likelihood sum_j ln E_j + I_j / E_j (constants dropped); per-frequency terms if `terms`.
double whittle_nll(const PartPeriodogram& p, const std::vector<double>& expected, std::vector<double>* terms = nullptr);

}  // namespace driftlab::host::gap
