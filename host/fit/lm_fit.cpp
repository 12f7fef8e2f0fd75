// Levenberg–Marquardt driver; see lm_fit.hpp.
#include "host/fit/lm_fit.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/SVD>

#include "host/fit/drift_functor.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::fit {
namespace {

/// Above this condition number of the column-scaled Jacobian the parameters are not separately determined
/// (e.g. T far beyond the record, where only the slope C1/T is seen).
constexpr double kSingularCondition = 1e9;

/// Data whose largest magnitude lies within 2^+-kUnscaledRange fit unscaled: their squares and sums are far from
/// a double's limits, and scaling would reorder MINPACK's column pivoting (the log T column scales, C1's and C2's do
/// not), moving an ill-conditioned fit's last digits.
constexpr int kUnscaledRange = 100;

/// The exponent of the largest finite magnitude in `y` (frexp's: 2^e just above it) when it lies outside the
/// unscaled range, else 0.
int scale_exponent(const std::vector<double>& y) {
    double largest = 0.0;
    for (double v : y)
        if (std::isfinite(v)) largest = std::max(largest, std::abs(v));
    int e = 0;
    std::frexp(largest, &e);
    return largest == 0.0 || std::abs(e) <= kUnscaledRange ? 0 : e;
}

const char* stop_reason(Eigen::LevenbergMarquardtSpace::Status s) {
    using namespace Eigen::LevenbergMarquardtSpace;
    switch (s) {
    case NotStarted: return "not started";
    case Running: return "running";
    case ImproperInputParameters: return "improper input parameters";
    case RelativeReductionTooSmall: return "relative reduction of the sum of squares below ftol";
    case RelativeErrorTooSmall: return "relative change of the parameters below xtol";
    case RelativeErrorAndReductionTooSmall: return "both ftol and xtol met";
    case CosinusTooSmall: return "residual orthogonal to the Jacobian (gtol)";
    case TooManyFunctionEvaluation: return "too many function evaluations";
    case FtolTooSmall: return "ftol too small, no further reduction possible";
    case XtolTooSmall: return "xtol too small, no further improvement possible";
    case GtolTooSmall: return "gtol too small, residual already orthogonal";
    case UserAsked: return "stopped by the model";
    }
    return "unknown";
}

}  // namespace

const char* fit_status_name(FitStatus s) {
    switch (s) {
    case FitStatus::converged: return "converged";
    case FitStatus::iteration_limit: return "iteration_limit";
    case FitStatus::singular: return "singular";
    }
    return "unknown";
}

const char* fit_status_words(FitStatus s) {
    // The JSON spelling iteration_limit read as a name in fit's table, not as a fit that stopped short.
    return s == FitStatus::iteration_limit ? "not converged (iteration limit)" : fit_status_name(s);
}

FitResult fit_drift(const std::vector<double>& t_s, const std::vector<double>& data, const FitOptions& options) {
    const std::size_t n = t_s.size();
    if (n < 4 || data.size() != n) throw UsageError("fit_drift: need at least 4 samples with one time each");
    FitResult out;
    out.n = n;
    out.scale_exponent = scale_exponent(data);
    const int e2 = out.scale_exponent;
    std::vector<double> scaled;  // only where scaling is needed: the gap diagnosis fits thousands of long series
    if (e2 != 0) {
        scaled.resize(n);
        for (std::size_t k = 0; k < n; ++k) scaled[k] = std::ldexp(data[k], -e2);
    }
    const std::vector<double>& y = e2 != 0 ? scaled : data;
    if (options.start) {
        out.start.parameters = {std::ldexp(options.start->c1, -e2), std::ldexp(options.start->c2, -e2),
                                options.start->t_s};
    } else {
        out.start = automatic_start(t_s, y);
    }

    DriftFunctor functor(t_s, y);
    Eigen::LevenbergMarquardt<DriftFunctor> lm(functor);
    lm.setMaxfev(options.max_function_evaluations);
    lm.setFtol(options.tolerance);
    lm.setXtol(options.tolerance);
    Eigen::VectorXd x(3);
    x << out.start.parameters.c1, out.start.parameters.c2, std::log(out.start.parameters.t_s);
    const auto stop = lm.minimize(x);
    out.solver_stop = stop_reason(stop);
    out.iterations = static_cast<int>(lm.iterations());
    out.function_evaluations = static_cast<int>(lm.nfev());
    const DriftParameters p{x[0], x[1], std::exp(x[2])};  // of the scaled data
    out.parameters = {std::ldexp(p.c1, e2), std::ldexp(p.c2, e2), p.t_s};

    out.residual.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double residual = y[k] - drift_model(p, t_s[k]);
        out.residual[k] = std::ldexp(residual, e2);
        out.scaled_rss += residual * residual;
    }
    out.rms = std::ldexp(std::sqrt(out.scaled_rss / static_cast<double>(n)), e2);
    // The functor's R of J over (C1, C2, log T) at the solution (its 4th row is |f|'s, zero in these columns);
    // d/dT = d/dlog T / T, so its last column over T is the R over (C1, C2, T) that the covariance reads.
    Eigen::MatrixXd r_log_t;
    functor.df(x, r_log_t);
    out.scaled_jacobian_r = r_log_t.topRows<3>();
    out.scaled_jacobian_r.col(2) /= p.t_s;
    const Eigen::Matrix3d& r = out.scaled_jacobian_r;
    // The columns of R have the norms of J's: scaled to unit columns, its singular values are J's.
    const Eigen::Vector3d scale = r.colwise().norm().transpose().cwiseMax(1e-300).cwiseInverse();
    const Eigen::Matrix3d unit_columns = r * scale.asDiagonal();
    const Eigen::Vector3d sv = Eigen::JacobiSVD<Eigen::Matrix3d>(unit_columns).singularValues();
    out.condition_number = sv[2] > 0.0 ? sv[0] / sv[2] : INFINITY;

    using namespace Eigen::LevenbergMarquardtSpace;
    if (!std::isfinite(out.scaled_rss) || !(out.condition_number < kSingularCondition))
        out.status = FitStatus::singular;
    else if (stop == TooManyFunctionEvaluation)
        out.status = FitStatus::iteration_limit;
    else
        out.status = FitStatus::converged;
    // A warm start that ran off is tried again cold: out of evaluations, or degenerate to the precision of its normal
    // equations (T run to 0 or to infinity, C1 to 0: a column of J exactly zero or equal to another); merely
    // ill-conditioned data are the data's, and stay.
    const bool warm = options.start.has_value();
    const auto degenerate = [&unit_columns] {
        const Eigen::Vector3d normal_sv =
            Eigen::JacobiSVD<Eigen::Matrix3d>(unit_columns.transpose() * unit_columns).singularValues();
        return !(normal_sv[2] > 0.0 && std::sqrt(normal_sv[0] / normal_sv[2]) < kSingularCondition);
    };
    if (warm && (out.status == FitStatus::iteration_limit || !std::isfinite(out.scaled_rss) || degenerate())) {
        FitOptions cold = options;
        cold.start.reset();
        return fit_drift(t_s, data, cold);
    }
    return out;
}

}  // namespace driftlab::host::fit
