// Levenberg–Marquardt fit of eq. 1 with Eigen's MINPACK port (unsupported/Eigen/LevenbergMarquardt),
// started by automatic_start(). docs/analysis.md §2.
#pragma once

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

struct FitOptions {
    int max_function_evaluations = 400;  ///< MINPACK maxfev
    double tolerance = 1e-10;            ///< relative ftol and xtol
    /// Start LM here instead of at automatic_start() (a log simulated from known parameters: the same optimum in a
    /// few iterations, no search). A start that does not converge falls back to the automatic one.
    std::optional<DriftParameters> start;
};

struct FitResult {
    DriftParameters parameters;
    FitStatus status = FitStatus::converged;
    std::string solver_stop;        ///< Eigen's stopping reason, for the curious
    int iterations = 0;
    int function_evaluations = 0;
    std::size_t n = 0;              ///< samples fitted
    double rss = 0.0;               ///< residual sum of squares [counts^2]
    double rms = 0.0;               ///< sqrt(rss / n) [counts]
    double condition_number = 0.0;  ///< of the column-scaled Jacobian (C1, C2, T)
    Eigen::Matrix3d jacobian_r = Eigen::Matrix3d::Zero();  ///< R of J = QR over (C1, C2, T) at the solution (R^T R = J^T J)
    std::vector<double> residual;   ///< data - model, per sample
    StartValues start;
};

/// Fits eq. 1 to (t_s, y). Needs at least 4 samples and strictly increasing t_s (the caller checks and
/// names the file; a violation here is a UsageError).
FitResult fit_drift(const std::vector<double>& t_s, const std::vector<double>& y, const FitOptions& options = {});

}  // namespace driftlab::host::fit
