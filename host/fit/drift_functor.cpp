// The streamed eq. 1 problem for Levenberg–Marquardt; see drift_functor.hpp.
#include "host/fit/drift_functor.hpp"

#include <cmath>
#include <cstddef>
#include <limits>

#include <Eigen/QR>

namespace driftlab::host::fit {
namespace {

/// Rows of a block: the 4 of R so far and 252 samples. Fixed-size, so a block lives on the stack: the reduction
/// allocates nothing.
constexpr int kBlockRows = 256;
using Block = Eigen::Matrix<double, kBlockRows, 4>;

}  // namespace

DriftFunctor::DriftFunctor(const std::vector<double>& t_s, const std::vector<double>& y)
    : Eigen::DenseFunctor<double>(3, 4), t_s_(t_s), y_(y) {}

const Eigen::Matrix4d& DriftFunctor::reduced(const InputType& x) const {
    if ((x.array() == last_x_.array()).all()) return last_r_;
    const double inv_t = std::exp(-x[2]);
    const std::size_t n = t_s_.size();
    Eigen::Matrix4d r = Eigen::Matrix4d::Zero();
    Block a;
    for (std::size_t k = 0; k < n;) {
        // Each block's QR takes R so far and the next samples' rows [d f / d (C1, C2, log T) | f]; rows past the last
        // sample are zero, which leaves R as it is.
        a.topRows<4>() = r;
        int row = 4;
        for (; row < kBlockRows && k < n; ++row, ++k) {
            const double u = t_s_[k] * inv_t;
            const double e = std::exp(-u);
            a(row, 0) = 1.0 - e;
            a(row, 1) = 1.0;
            a(row, 2) = -x[0] * e * u;
            a(row, 3) = x[0] * -std::expm1(-u) + x[1] - y_[k];
        }
        a.bottomRows(kBlockRows - row).setZero();
        r = Eigen::HouseholderQR<Block>(a).matrixQR().topRows<4>().triangularView<Eigen::Upper>();
    }
    last_x_ = x;
    last_r_ = r;
    return last_r_;
}

int DriftFunctor::operator()(const InputType& x, ValueType& fvec) const {
    const Eigen::Matrix4d& r = reduced(x);
    // A trial step that overflowed the model: an infinite |f|, which LM rejects as it would the residuals themselves.
    if (r.allFinite())
        fvec = r.col(3);
    else
        fvec.setConstant(4, std::numeric_limits<double>::infinity());
    return 0;
}

int DriftFunctor::df(const InputType& x, JacobianType& fjac) const {
    fjac = reduced(x).leftCols<3>();
    return 0;
}

}  // namespace driftlab::host::fit
