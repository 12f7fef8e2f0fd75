// IEEE 952 term fit by non-negative weighted least squares on AVAR (docs/allan.md §6).
#include "host/stats/noise_terms.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "host/stats/rate_unit.hpp"

namespace driftlab::host::stats {
namespace {

// AVAR = sum_j c_j * tau^(j-2): c = (3 Q^2, N^2, (2 ln2/pi) B^2, K^2/3, R^2/2).
constexpr std::array<double, kNoiseTermCount> kCoefficientScale = {
    3.0, 1.0, kBiasInstabilityFactor* kBiasInstabilityFactor, 1.0 / 3.0, 0.5};

double basis(std::size_t j, double tau_s) { return std::pow(tau_s, static_cast<double>(j) - 2.0); }

struct SubsetSolution {
    Eigen::VectorXd c;    // AVAR coefficients over all terms (zeros outside the subset)
    Eigen::MatrixXd cov;  // covariance of the subset's coefficients
    double cost = std::numeric_limits<double>::infinity();
};

// Non-negative WLS with five unknowns: solve every subset of terms unconstrained and keep the cheapest one
// whose coefficients are all >= 0. This is the exact NNLS optimum (the optimum is an unconstrained optimum on
// its own support) and never stalls the way active-set iterations can on badly scaled columns.
SubsetSolution solve_nnls(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, unsigned enabled_mask) {
    SubsetSolution best;
    const Eigen::Index k = a.cols();
    for (unsigned subset = 1; subset < (1u << k); ++subset) {
        if ((subset & ~enabled_mask) != 0) continue;
        std::vector<Eigen::Index> cols;
        for (Eigen::Index j = 0; j < k; ++j) {
            if (subset & (1u << j)) cols.push_back(j);
        }
        if (static_cast<Eigen::Index>(cols.size()) > a.rows()) continue;
        Eigen::MatrixXd as(a.rows(), static_cast<Eigen::Index>(cols.size()));
        Eigen::VectorXd norms(as.cols());
        for (Eigen::Index c = 0; c < as.cols(); ++c) {
            as.col(c) = a.col(cols[static_cast<std::size_t>(c)]);
            norms(c) = as.col(c).norm();
            if (norms(c) > 0.0) as.col(c) /= norms(c);  // equilibrate: tau^-2 .. tau^2 span many decades
        }
        const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(as);
        if (qr.rank() < as.cols()) continue;
        const Eigen::VectorXd xs = qr.solve(b);
        if ((xs.array() < 0.0).any()) continue;
        const double cost = (as * xs - b).squaredNorm();
        if (cost < best.cost) {
            best.cost = cost;
            best.c = Eigen::VectorXd::Zero(k);
            const Eigen::MatrixXd inv_normal = (as.transpose() * as).inverse();
            best.cov = Eigen::MatrixXd::Zero(k, k);
            for (Eigen::Index r = 0; r < as.cols(); ++r) {
                best.c(cols[static_cast<std::size_t>(r)]) = xs(r) / norms(r);
                for (Eigen::Index s = 0; s < as.cols(); ++s) {
                    best.cov(cols[static_cast<std::size_t>(r)], cols[static_cast<std::size_t>(s)]) =
                        inv_normal(r, s) / (norms(r) * norms(s));
                }
            }
        }
    }
    return best;
}

// Iteratively reweighted NNLS on the scaled AVAR y^2 at the points `use`; its last cost is the chi-square.
SubsetSolution reweighted_fit(std::span<const double> tau_s, std::span<const double> edf, const std::vector<double>& y,
                              const std::vector<std::size_t>& use, const NoiseTermOptions& options,
                              double& chi_square) {
    unsigned mask = 0;
    for (std::size_t j = 0; j < kNoiseTermCount; ++j) {
        if (options.enabled[j]) mask |= 1u << j;
    }
    const auto rows = static_cast<Eigen::Index>(use.size());
    Eigen::VectorXd model(rows);
    for (Eigen::Index r = 0; r < rows; ++r)
        model(r) = y[use[static_cast<std::size_t>(r)]] * y[use[static_cast<std::size_t>(r)]];

    SubsetSolution sol;
    for (int it = 0; it <= options.reweight_iterations; ++it) {
        // Row r scaled by sqrt(w) = sqrt(edf / 2) / AVAR_model: a relative (log-like) fit where EDF is high.
        Eigen::MatrixXd a(rows, static_cast<Eigen::Index>(kNoiseTermCount));
        Eigen::VectorXd b(rows);
        for (Eigen::Index r = 0; r < rows; ++r) {
            const std::size_t i = use[static_cast<std::size_t>(r)];
            const double sw = std::sqrt(edf[i] / 2.0) / model(r);
            for (std::size_t j = 0; j < kNoiseTermCount; ++j)
                a(r, static_cast<Eigen::Index>(j)) = sw * basis(j, tau_s[i]);
            b(r) = sw * y[i] * y[i];
        }
        SubsetSolution next = solve_nnls(a, b, mask);
        if (!std::isfinite(next.cost)) break;
        sol = next;
        for (Eigen::Index r = 0; r < rows; ++r) {
            double v = 0.0;
            for (std::size_t j = 0; j < kNoiseTermCount; ++j)
                v += sol.c(static_cast<Eigen::Index>(j)) * basis(j, tau_s[use[static_cast<std::size_t>(r)]]);
            // Keep the weights finite where the model vanishes (a term fitted to zero at the curve's end).
            model(r) = std::max(v, 1e-6 * y[use[static_cast<std::size_t>(r)]] * y[use[static_cast<std::size_t>(r)]]);
        }
        chi_square = sol.cost;
    }
    return sol;
}

// Term values and standard errors from the AVAR coefficients; a term fitted to zero gets its upper bound instead.
void unpack_terms(const SubsetSolution& sol, std::span<const double> tau_s, const std::vector<double>& y,
                  const std::vector<std::size_t>& use, const NoiseTermOptions& options, NoiseTermFit& fit) {
    for (std::size_t j = 0; j < kNoiseTermCount; ++j) {
        const auto jj = static_cast<Eigen::Index>(j);
        const double c = sol.c(jj);
        fit.value[j] = std::sqrt(c / kCoefficientScale[j]);
        // d value / d c = 1 / (2 sqrt(c * scale)).
        fit.std_error[j] =
            c > 0.0 ? std::sqrt(std::max(sol.cov(jj, jj), 0.0)) / (2.0 * std::sqrt(c * kCoefficientScale[j])) : 0.0;
        fit.at_bound[j] = options.enabled[j] && c <= 0.0;
        fit.upper_bound[j] = std::numeric_limits<double>::quiet_NaN();
        if (!fit.at_bound[j]) continue;
        // The term alone may not exceed the curve anywhere: value^2 scale tau^(j-2) <= adev^2 at every tau.
        double bound = std::numeric_limits<double>::infinity();
        for (std::size_t i : use) {
            bound = std::min(bound, y[i] * std::pow(tau_s[i], (2.0 - static_cast<double>(j)) / 2.0) /
                                        std::sqrt(kCoefficientScale[j]));
        }
        fit.upper_bound[j] = bound;
    }
}

}  // namespace

double noise_term_avar(const std::array<double, kNoiseTermCount>& value, double tau_s) {
    double avar = 0.0;
    for (std::size_t j = 0; j < kNoiseTermCount; ++j) {
        avar += kCoefficientScale[j] * value[j] * value[j] * basis(j, tau_s);
    }
    return avar;
}

NoiseTermFit fit_noise_terms(std::span<const double> tau_s, std::span<const double> adev, std::span<const double> edf,
                             const NoiseTermOptions& options) {
    if (tau_s.size() != adev.size() || tau_s.size() != edf.size()) {
        throw std::invalid_argument("noise term fit: tau, adev and edf differ in length");
    }
    NoiseTermFit fit;
    std::vector<std::size_t> use;
    for (std::size_t i = 0; i < tau_s.size(); ++i) {
        if (std::isfinite(adev[i]) && adev[i] > 0.0 && tau_s[i] > 0.0 && std::isfinite(edf[i]) && edf[i] > 0.0) {
            use.push_back(i);
        }
    }
    fit.points = static_cast<int>(use.size());
    fit.model_adev.assign(tau_s.size(), std::nan(""));
    if (use.empty()) return fit;
    // AVAR squares the deviation: fit the deviation divided by a power of two that brings its largest value
    // near 1 (no bit changes), so that 1e-170 or 1e200 neither underflows nor overflows; scaled back at the end.
    double largest = 0.0;
    for (std::size_t i : use) largest = std::max(largest, adev[i]);
    int exponent = 0;
    std::frexp(largest, &exponent);
    std::vector<double> y(adev.size(), 0.0);
    for (std::size_t i : use) y[i] = std::ldexp(adev[i], -exponent);

    SubsetSolution sol = reweighted_fit(tau_s, edf, y, use, options, fit.chi_square);
    if (!std::isfinite(sol.cost)) return fit;
    unpack_terms(sol, tau_s, y, use, options, fit);
    for (std::size_t i = 0; i < tau_s.size(); ++i) {
        if (tau_s[i] > 0.0) fit.model_adev[i] = std::ldexp(std::sqrt(noise_term_avar(fit.value, tau_s[i])), exponent);
    }
    for (std::size_t j = 0; j < kNoiseTermCount; ++j) {
        fit.value[j] = std::ldexp(fit.value[j], exponent);
        fit.std_error[j] = std::ldexp(fit.std_error[j], exponent);
        fit.upper_bound[j] = std::ldexp(fit.upper_bound[j], exponent);
    }
    fit.ok = true;
    return fit;
}

namespace {

// Term `term` in data units times `si_per_unit`, then `convert`ed; an unresolved term has no value, only its bound.
template <class Convert>
NamedValue term_value(std::string key, const NoiseTermFit& fit, std::size_t term, double si_per_unit, Convert convert) {
    const bool resolved = !fit.at_bound[term];
    return {std::move(key),
            resolved ? convert(fit.value[term] * si_per_unit) : std::numeric_limits<double>::quiet_NaN(), resolved,
            convert(fit.upper_bound[term] * si_per_unit)};
}

}  // namespace

std::vector<NamedValue> physical_terms(const NoiseTermFit& fit, RateQuantity quantity, double si_per_unit) {
    if (!fit.ok || quantity == RateQuantity::unknown) return {};
    constexpr double kSqrtHourS = 60.0;  // sqrt(3600 s)
    constexpr double kHourS = 3600.0;
    constexpr std::size_t q = 0, n = 1, b = 2, k = 3, r = 4;
    const auto si = [](double x) { return x; };
    if (quantity == RateQuantity::angular_rate) {
        constexpr double kDegPerRad = 180.0 / std::numbers::pi;
        const auto deg = [](double x) { return x * kDegPerRad; };
        return {
            term_value("Q_deg", fit, q, si_per_unit, deg),
            term_value("N_deg_per_s_per_sqrt_hz", fit, n, si_per_unit, deg),
            term_value("N_deg_per_sqrt_h", fit, n, si_per_unit, [](double x) { return x * kDegPerRad * kSqrtHourS; }),
            term_value("B_deg_per_s", fit, b, si_per_unit, deg),
            term_value("B_deg_per_h", fit, b, si_per_unit, [](double x) { return x * kDegPerRad * kHourS; }),
            term_value("K_deg_per_s_per_sqrt_s", fit, k, si_per_unit, deg),
            term_value("K_deg_per_h_per_sqrt_h", fit, k, si_per_unit,
                       [](double x) { return x * kDegPerRad * kHourS * kSqrtHourS; }),
            term_value("R_deg_per_s2", fit, r, si_per_unit, deg),
            term_value("R_deg_per_h2", fit, r, si_per_unit, [](double x) { return x * kDegPerRad * kHourS * kHourS; })};
    }
    return {term_value("Q_m_per_s", fit, q, si_per_unit, si),
            term_value("N_m_per_s2_per_sqrt_hz", fit, n, si_per_unit, si),
            term_value("N_m_per_s_per_sqrt_h", fit, n, si_per_unit, [](double x) { return x * kSqrtHourS; }),
            term_value("B_m_per_s2", fit, b, si_per_unit, si),
            term_value("B_mg", fit, b, si_per_unit, [](double x) { return x / kStandardGravity * 1000.0; }),
            term_value("K_m_per_s2_per_sqrt_s", fit, k, si_per_unit, si),
            term_value("R_m_per_s3", fit, r, si_per_unit, si)};
}

std::vector<NamedValue> kalibr_densities(const NoiseTermFit& fit, RateQuantity quantity, double si_per_unit) {
    if (!fit.ok || quantity == RateQuantity::unknown) return {};
    const std::string prefix = quantity == RateQuantity::angular_rate ? "gyroscope" : "accelerometer";
    const auto si = [](double x) { return x; };
    return {term_value(prefix + "_noise_density", fit, 1, si_per_unit, si),
            term_value(prefix + "_random_walk", fit, 3, si_per_unit, si)};
}

}  // namespace driftlab::host::stats
