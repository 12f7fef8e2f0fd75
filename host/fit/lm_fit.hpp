// Levenberg–Marquardt fit of eq. 1 with Eigen's MINPACK port (unsupported/Eigen/LevenbergMarquardt),
// started by automatic_start(). docs/analysis.md §2.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "host/fit/drift_model.hpp"
#include "host/fit/start_values.hpp"

namespace driftlab::host::fit {

/// How the fit ended: a result, not an error (like Eigen's info()).
enum class FitStatus {
    converged,        ///< a MINPACK tolerance was met and the Jacobian has full rank
    iteration_limit,  ///< the evaluation budget ran out first; the parameters are the last iterate
    singular,         ///< the Jacobian is rank deficient at the end: C1, C2, T not all identifiable
};

/// "converged", "iteration_limit", "singular" (the JSON spelling).
const char* fit_status_name(FitStatus s);

/// The status in words for a person at a terminal: "converged", "not converged (iteration limit)", "singular".
const char* fit_status_words(FitStatus s);

struct FitOptions {
    int max_function_evaluations = 400;  ///< MINPACK maxfev
    double tolerance = 1e-10;            ///< relative ftol and xtol
    /// Start LM here instead of at automatic_start() (a log simulated from known parameters: the same optimum in a
    /// few iterations, no search). A start that does not converge falls back to the automatic one.
    std::optional<DriftParameters> start;
};

/// Data whose largest magnitude lies beyond 2^+-100 are fitted divided by 2^scale_exponent, a power of two that
/// brings that magnitude near 1 (eq. 1 is linear in C1 and C2, so the fit scales with them), so that data near
/// 1e-170 or 1e200 neither underflow nor overflow; other data fit unscaled (scale_exponent 0). The sum of squares
/// and R are kept in the scaled units, since at 1e200 the sum of squares itself is beyond a double; everything else
/// is in the data's unit.
struct FitResult {
    DriftParameters parameters;
    FitStatus status = FitStatus::converged;
    std::string solver_stop;  ///< Eigen's stopping reason, for the curious
    int iterations = 0;
    int function_evaluations = 0;
    std::size_t n = 0;              ///< samples fitted
    int scale_exponent = 0;         ///< the data were divided by 2^scale_exponent for the fit
    double scaled_rss = 0.0;        ///< residual sum of squares of the scaled data
    double rms = 0.0;               ///< sqrt(rss / n) [counts]
    double condition_number = 0.0;  ///< of the column-scaled Jacobian (C1, C2, T)
    /// R of J = QR over (C1, C2, T) at the solution for the scaled data (R^T R = J^T J)
    Eigen::Matrix3d scaled_jacobian_r = Eigen::Matrix3d::Zero();
    std::vector<double> residual;  ///< data - model, per sample
    StartValues start;             ///< of the scaled data (T and the flags are the data's)

    /// Residual sum of squares [counts^2]; infinite where it is beyond a double.
    double rss() const { return std::ldexp(scaled_rss, 2 * scale_exponent); }
};

/// Fits eq. 1 to (t_s, y). Needs at least 4 samples and strictly increasing t_s (the caller checks and
/// names the file; a violation here is a UsageError).
FitResult fit_drift(const std::vector<double>& t_s, const std::vector<double>& y, const FitOptions& options = {});

}  // namespace driftlab::host::fit
