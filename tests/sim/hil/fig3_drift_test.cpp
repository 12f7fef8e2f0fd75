// Fig. 3 / Table 1 from a host-in-the-loop log: a plain least-squares fit of eq. 1 to each channel of the default
// run (4000 outputs a second apart from power-on) must recover the paper's Table 1 within the fit's 95 %
// intervals. The fit is written here (Levenberg–Marquardt on three parameters, covariance s²(JᵀJ)⁻¹), independent
// of the simulator and of host/fit.
#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "tests/sim/hil/hil_test_support.hpp"

namespace driftlab::sim {
namespace {

using testing::preset;
using testing::run_into_memory;

struct Fit {
    Eigen::Vector3d p;   // C1 [counts], C2 [counts], T [s]
    Eigen::Vector3d se;  // standard errors
};

// eq. 1 residuals r = y - model and Jacobian of the model.
double model(const Eigen::Vector3d& p, double t) { return p(0) * (1.0 - std::exp(-t / p(2))) + p(1); }

Fit fit_eq1(const std::vector<double>& t, const std::vector<double>& y) {
    const auto n = static_cast<Eigen::Index>(t.size());
    auto evaluate = [&](const Eigen::Vector3d& p, Eigen::VectorXd& r, Eigen::MatrixXd& J) {
        r.resize(n);
        J.resize(n, 3);
        for (Eigen::Index i = 0; i < n; ++i) {
            const double e = std::exp(-t[i] / p(2));
            r(i) = y[i] - model(p, t[i]);
            J(i, 0) = 1.0 - e;
            J(i, 1) = 1.0;
            J(i, 2) = -p(0) * e * t[i] / (p(2) * p(2));
        }
    };
    // Start: C2 from the first outputs, C1 from the last, T from the span.
    double head = 0.0, tail = 0.0;
    for (int i = 0; i < 20; ++i) head += y[i] / 20.0;
    for (std::size_t i = y.size() - 200; i < y.size(); ++i) tail += y[i] / 200.0;
    Eigen::Vector3d p(tail - head, head, t.back() / 8.0);
    Eigen::VectorXd r;
    Eigen::MatrixXd J;
    evaluate(p, r, J);
    double lambda = 1e-3;
    for (int it = 0; it < 200; ++it) {
        const Eigen::Matrix3d A = J.transpose() * J;
        const Eigen::Vector3d g = J.transpose() * r;
        Eigen::Matrix3d D = A;
        D.diagonal() *= (1.0 + lambda);
        const Eigen::Vector3d step = D.ldlt().solve(g);
        Eigen::Vector3d trial = p + step;
        if (trial(2) <= 0.0) trial(2) = p(2) / 2.0;
        Eigen::VectorXd r2;
        Eigen::MatrixXd J2;
        evaluate(trial, r2, J2);
        if (r2.squaredNorm() < r.squaredNorm()) {
            const bool converged = (step.array().abs() < 1e-10 * (p.array().abs() + 1e-10)).all();
            p = trial;
            r = r2;
            J = J2;
            lambda = std::max(lambda / 10.0, 1e-12);
            if (converged) break;
        } else {
            lambda *= 10.0;
            if (lambda > 1e12) break;
        }
    }
    const double s2 = r.squaredNorm() / static_cast<double>(n - 3);
    const Eigen::Matrix3d cov = s2 * (J.transpose() * J).inverse();
    return {p, cov.diagonal().cwiseSqrt()};
}

TEST(Fig3Preset, DefaultRunGivesFourThousandOutputsOneSecondApart) {
    const auto run = run_into_memory(preset(Preset::fig3));
    ASSERT_EQ(run.rows.size(), 4000u);
    EXPECT_NEAR(run.rows.back().t_s - run.rows.front().t_s, 3999.0, 0.05);
    EXPECT_LT(run.rows.front().t_s, 1.5);
}

TEST(Fig3Preset, FittingEquationOneToTheLogRecoversTableOneWithinThe95PercentIntervals) {
    const auto run = run_into_memory(preset(Preset::fig3));
    ASSERT_EQ(run.rows.size(), 4000u);
    const double table1[4][3] = {{3, 505, 411}, {2, 470, 953}, {23, 474, 937}, {28, 622, 1050}};
    // Twelve intervals are checked at once; Bonferroni keeps the family-wise level at 95 %: each interval is
    // ±z·se with z = Φ⁻¹(1 - 0.05/24) = 2.865, so a correct simulator fails this test with probability < 5 %
    // over seeds (and never for the fixed seed it runs with).
    const double z = 2.865;
    const char* const kNames[3] = {"C1", "C2", "T"};
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        std::vector<double> t, y;
        for (const auto& r : run.rows) {
            t.push_back(r.t_s);
            y.push_back(r.value_counts[c]);
        }
        const Fit f = fit_eq1(t, y);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(f.p(k), table1[c][k], z * f.se(k))
                << kChannelNames[c] << " " << kNames[k] << " fitted " << f.p(k) << " ± " << f.se(k);
        }
        // The intervals must be informative, not wide enough to hold anything.
        EXPECT_LT(f.se(2), 0.15 * table1[c][2]) << kChannelNames[c];
    }
}

}  // namespace
}  // namespace driftlab::sim
