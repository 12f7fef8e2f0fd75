// The streamed eq. 1 problem against the residuals and Jacobian written out in long double: what Levenberg–Marquardt
// reads of them (|f|, J^T J, J^T f) must be the same, whatever the number of samples against the block size.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "host/fit/drift_functor.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::host::fit {
namespace {

using LongMatrix3 = Eigen::Matrix<long double, 3, 3>;
using LongVector3 = Eigen::Matrix<long double, 3, 1>;

/// The n residuals model - data and their Jacobian over (C1, C2, log T), reduced in long double to what LM reads.
struct Direct {
    long double norm_f = 0.0L;
    LongMatrix3 jtj = LongMatrix3::Zero();
    LongVector3 jtf = LongVector3::Zero();
};

Direct direct(const std::vector<double>& t_s, const std::vector<double>& y, const Eigen::Vector3d& x) {
    Direct d;
    long double ss = 0.0L;
    const long double t_const = std::exp(static_cast<long double>(x[2]));
    for (std::size_t k = 0; k < t_s.size(); ++k) {
        const long double u = t_s[k] / t_const;
        const long double e = std::exp(-u);
        const long double f = x[0] * (1.0L - e) + x[1] - y[k];
        const LongVector3 j(1.0L - e, 1.0L, -x[0] * e * u);
        ss += f * f;
        d.jtj += j * j.transpose();
        d.jtf += j * f;
    }
    d.norm_f = std::sqrt(ss);
    return d;
}

/// Drifting data with noise at n times 0.5 s apart, from 0.5 s on.
void make_data(std::size_t n, std::vector<double>& t_s, std::vector<double>& y) {
    sim::Rng rng(n, 3);
    for (std::size_t k = 0; k < n; ++k) {
        const double t = 0.5 * static_cast<double>(k + 1);
        t_s.push_back(t);
        y.push_back(12.0 * (1.0 - std::exp(-t / 300.0)) + 500.0 + 2.0 * rng.normal());
    }
}

TEST(DriftFunctor, ItsValuesAndJacobianGiveLmWhatTheResidualsThemselvesWould) {
    // Fewer samples than one block, one block exactly (252 samples beside R's 4 rows), one more, and many blocks
    // ending part-way: a stale row from an earlier block would show in J^T J.
    for (const std::size_t n : {5u, 252u, 253u, 504u, 10007u}) {
        std::vector<double> t_s, y;
        make_data(n, t_s, y);
        const DriftFunctor functor(t_s, y);
        ASSERT_EQ(functor.values(), 4);
        ASSERT_EQ(functor.inputs(), 3);
        // Away from the optimum (the start LM is given) and near it.
        for (const Eigen::Vector3d& x :
             {Eigen::Vector3d(3.0, 490.0, std::log(40.0)), Eigen::Vector3d(12.0, 500.0, std::log(300.0))}) {
            Eigen::VectorXd fvec(4);
            Eigen::MatrixXd fjac(4, 3);
            ASSERT_EQ(functor(x, fvec), 0);
            ASSERT_EQ(functor.df(x, fjac), 0);
            const Direct d = direct(t_s, y, x);
            const auto tag = ::testing::Message() << "n = " << n << ", x = " << x.transpose();
            EXPECT_NEAR(fvec.norm(), static_cast<double>(d.norm_f), 1e-12 * static_cast<double>(d.norm_f)) << tag;
            // Triangular, its last row zero: LM's QR of it is R again.
            EXPECT_TRUE(Eigen::MatrixXd(fjac.triangularView<Eigen::StrictlyLower>()).isZero(0.0)) << tag << "\n"
                                                                                                  << fjac;
            const Eigen::Matrix3d jtj = fjac.transpose() * fjac;
            const Eigen::Vector3d jtf = fjac.transpose() * fvec;
            for (int i = 0; i < 3; ++i) {
                const double scale_i = std::sqrt(static_cast<double>(d.jtj(i, i)));
                for (int k = 0; k < 3; ++k) {
                    const double scale = scale_i * std::sqrt(static_cast<double>(d.jtj(k, k)));
                    EXPECT_NEAR(jtj(i, k), static_cast<double>(d.jtj(i, k)), 1e-12 * scale)
                        << tag << " J^T J(" << i << "," << k << ")";
                }
                EXPECT_NEAR(jtf[i], static_cast<double>(d.jtf[i]), 1e-12 * scale_i * static_cast<double>(d.norm_f))
                    << tag << " J^T f(" << i << ")";
            }
        }
    }
}

TEST(DriftFunctor, ATrialStepThatOverflowsTheModelHasAnInfiniteNorm) {
    std::vector<double> t_s, y;
    make_data(300, t_s, y);
    const DriftFunctor functor(t_s, y);
    Eigen::VectorXd fvec(4);
    ASSERT_EQ(functor(Eigen::Vector3d(1e308, 1e308, std::log(300.0)), fvec), 0);
    EXPECT_TRUE(std::isinf(fvec.norm())) << fvec.transpose();
    // The next point is reduced afresh, not read from the one before.
    ASSERT_EQ(functor(Eigen::Vector3d(12.0, 500.0, std::log(300.0)), fvec), 0);
    EXPECT_TRUE(std::isfinite(fvec.norm())) << fvec.transpose();
    EXPECT_NEAR(fvec.norm(), static_cast<double>(direct(t_s, y, Eigen::Vector3d(12.0, 500.0, std::log(300.0))).norm_f),
                1e-9);
}

}  // namespace
}  // namespace driftlab::host::fit
