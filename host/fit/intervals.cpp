// Parameter intervals; see intervals.hpp.
#include "host/fit/intervals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/LU>
#include <boost/math/distributions/students_t.hpp>

#include "host/util/format_number.hpp"

namespace driftlab::host::fit {
namespace {

Estimate estimate(double value, double scaled_variance, double inflation, double q, int scale_exponent) {
    Estimate e;
    e.value = value;
    e.stderr_ = std::ldexp(std::sqrt(std::max(0.0, scaled_variance)) * inflation, scale_exponent);
    e.ci95 = {value - q * e.stderr_, value + q * e.stderr_};
    return e;
}

}  // namespace

std::string with_error(const Estimate& e) {
    // A singular fit has no standard errors: "+- inf" had been printed as if it were one.
    if (!std::isfinite(e.stderr_)) return to_precision_of(e.value, e.stderr_) + " (no interval: the fit is singular)";
    return value_with_error(e.value, e.stderr_, "+-");
}

ParameterIntervals parameter_intervals(const FitResult& fit, double tau) {
    ParameterIntervals out;
    tau = std::max(1.0, tau);
    out.inflation = std::sqrt(tau);
    const double n = static_cast<double>(fit.n);
    out.dof = n / tau - 3.0;
    const double inf = std::numeric_limits<double>::infinity();
    Eigen::Matrix3d cov = Eigen::Matrix3d::Constant(inf);
    const DriftParameters& p = fit.parameters;
    // d(C1/T) / d(C1, C2, T) for the scaled data.
    const Eigen::Vector3d slope_gradient(1.0 / p.t_s, 0.0, -std::ldexp(p.c1, -fit.scale_exponent) / (p.t_s * p.t_s));
    double slope_variance = inf;
    if (fit.n > 3 && fit.status != FitStatus::singular) {
        const double s2 = fit.scaled_rss / (n - 3.0);
        // (J^T J)^-1 = R^-1 R^-T: a sum of squares on the diagonal, never the negative variance inverting an
        // ill-conditioned J^T J could give.
        const auto r = fit.scaled_jacobian_r.triangularView<Eigen::Upper>();
        const Eigen::Matrix3d r_inv = r.solve(Eigen::Matrix3d::Identity());
        cov = s2 * r_inv * r_inv.transpose();
        // g^T (J^T J)^-1 g = |R^-T g|^2, solved rather than summed from cov, whose large entries cancel along the
        // slope where T is far beyond the record.
        slope_variance = s2 * r.transpose().solve(slope_gradient).squaredNorm();
    }
    out.t_quantile = out.dof > 0.0 ? boost::math::quantile(boost::math::students_t(out.dof), 0.975) : inf;
    // The covariance is the scaled data's: C1's and C2's standard errors scale back with the data, T's is T's.
    out.c1 = estimate(p.c1, cov(0, 0), out.inflation, out.t_quantile, fit.scale_exponent);
    out.c2 = estimate(p.c2, cov(1, 1), out.inflation, out.t_quantile, fit.scale_exponent);
    out.t_s = estimate(p.t_s, cov(2, 2), out.inflation, out.t_quantile, 0);
    out.initial_slope = estimate(p.c1 / p.t_s, slope_variance, out.inflation, out.t_quantile, fit.scale_exponent);
    // T > 0 and its estimate is right-skewed: the interval is symmetric in log T (delta method,
    // se(log T) = se(T) / T), which keeps the nominal coverage when T is loosely determined.
    const double half_width_log = out.t_quantile * out.t_s.stderr_ / p.t_s;
    out.t_s.ci95 = {p.t_s * std::exp(-half_width_log), p.t_s * std::exp(half_width_log)};
    return out;
}

}  // namespace driftlab::host::fit
