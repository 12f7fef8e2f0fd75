// Eq. 1's least-squares problem in the shape Eigen's LevenbergMarquardt wants (a DenseFunctor), streamed: the
// solver sees the 4 x 4 triangular factor of [J | f] over every sample instead of J and f themselves, so its working
// set does not grow with the log. docs/analysis.md §2.
#pragma once

#include <limits>
#include <vector>

#include <Eigen/Core>
#include <unsupported/Eigen/LevenbergMarquardt>

namespace driftlab::host::fit {

/// LM functor over x = (C1, C2, log T). Optimising log T keeps T positive whatever step LM tries and makes the
/// problem better scaled; the covariance is reported for T itself (intervals.hpp).
///
/// The residuals f = model - data and their Jacobian J (n x 3) are reduced, block by block, to the upper-triangular
/// R of [J | f] = Q R. Its first three columns are the R of J, its last column Q^T f, whose norm is |f|: the
/// values are that column (4 of them) and the Jacobian is R's first three columns. Levenberg–Marquardt reads only
/// |f|, the column norms of J, R and Q^T f, all of which the reduction keeps, so it takes the same steps as on the
/// n residuals themselves (to rounding) while holding 4 x 4 numbers instead of 3 x n several times over.
class DriftFunctor : public Eigen::DenseFunctor<double> {
public:
    DriftFunctor(const std::vector<double>& t_s, const std::vector<double>& y);

    /// The last column of R at x: Q^T f, then |f| beyond it (infinite where a residual is not finite).
    int operator()(const InputType& x, ValueType& fvec) const;

    /// The first three columns of R at x: d values / d (C1, C2, log T), as LM reads it.
    int df(const InputType& x, JacobianType& fjac) const;

private:
    /// R of [J | f] at x; kept for the x it was last computed at, since LM asks df where it has just asked values.
    const Eigen::Matrix4d& reduced(const InputType& x) const;

    const std::vector<double>& t_s_;
    const std::vector<double>& y_;
    mutable Eigen::Vector3d last_x_ = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    mutable Eigen::Matrix4d last_r_ = Eigen::Matrix4d::Zero();
};

}  // namespace driftlab::host::fit
