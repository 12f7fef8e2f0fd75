// The turn-on drift model, paper eq. 1: eps(t) = C1 (1 - exp(-t/T)) + C2, with t the time since power-on,
// as residuals and Jacobian in the shape Eigen's LevenbergMarquardt wants (a DenseFunctor).
// docs/analysis.md §2.
#pragma once

#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <unsupported/Eigen/LevenbergMarquardt>

namespace driftlab::host::fit {

/// Eq. 1 parameters. C1 and C2 in the unit of the data (A/D counts for a canonical log), T in seconds.
struct DriftParameters {
    double c1 = 0.0;  ///< amplitude of the transient [counts]
    double c2 = 0.0;  ///< value at power-on [counts]; settles at C1 + C2
    double t_s = 1.0; ///< time constant T [s]
};

/// Eq. 1 at time t [s].
inline double drift_model(const DriftParameters& p, double t_s) { return p.c1 * -std::expm1(-t_s / p.t_s) + p.c2; }

/// LM functor over x = (C1, C2, log T). Optimising log T keeps T positive whatever step LM tries and makes the
/// problem better scaled; the covariance is reported for T itself (intervals.hpp).
struct DriftFunctor : Eigen::DenseFunctor<double> {
    DriftFunctor(const std::vector<double>& t_s, const std::vector<double>& y)
        : Eigen::DenseFunctor<double>(3, static_cast<int>(t_s.size())), t_s_(t_s), y_(y) {}

    /// Residuals model - data.
    int operator()(const InputType& x, ValueType& fvec) const {
        const double inv_t = std::exp(-x[2]);
        for (Eigen::Index k = 0; k < fvec.size(); ++k) {
            const auto i = static_cast<std::size_t>(k);
            fvec[k] = x[0] * -std::expm1(-t_s_[i] * inv_t) + x[1] - y_[i];
        }
        return 0;
    }

    /// d residual / d (C1, C2, log T).
    int df(const InputType& x, JacobianType& fjac) const {
        const double inv_t = std::exp(-x[2]);
        for (Eigen::Index k = 0; k < fjac.rows(); ++k) {
            const double u = t_s_[static_cast<std::size_t>(k)] * inv_t;
            const double e = std::exp(-u);
            fjac(k, 0) = 1.0 - e;
            fjac(k, 1) = 1.0;
            fjac(k, 2) = -x[0] * e * u;
        }
        return 0;
    }

private:
    const std::vector<double>& t_s_;
    const std::vector<double>& y_;
};

}  // namespace driftlab::host::fit
