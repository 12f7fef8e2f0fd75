// Variable-projection fits of the deterministic candidates; see mean_shapes.hpp.
#include "host/gap/mean_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>

#include "host/gap/nelder_mead.hpp"

namespace driftlab::host::gap {

namespace {

constexpr int kGridPoints = 24;
constexpr int kRefineEvaluations = 120;

// Least squares of y on the columns of X; returns the coefficients and the residual sum of squares.
double project(const Eigen::MatrixXd& x, const Eigen::VectorXd& y, Eigen::VectorXd& beta) {
    beta = x.colPivHouseholderQr().solve(y);
    return (y - x * beta).squaredNorm();
}

Eigen::VectorXd rise(const std::vector<double>& t_s, std::size_t n, double tau_s) {
    Eigen::VectorXd v(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) v(static_cast<Eigen::Index>(i)) = -std::expm1(-t_s[i] / tau_s);
    return v;
}

std::vector<double> log_grid(double lo, double hi, int points) {
    std::vector<double> g(static_cast<std::size_t>(points));
    for (int i = 0; i < points; ++i) g[static_cast<std::size_t>(i)] = lo * std::pow(hi / lo, i / double(points - 1));
    return g;
}

}  // namespace

TwoExponentials fit_two_exponentials(const std::vector<double>& t_s, const std::vector<double>& y, std::size_t n) {
    const Eigen::Map<const Eigen::VectorXd> yv(y.data(), static_cast<Eigen::Index>(n));
    const double dt = (t_s[n - 1] - t_s[0]) / static_cast<double>(n - 1);
    const double span = t_s[n - 1];
    auto rss_at = [&](double a, double b, Eigen::VectorXd& beta) {
        Eigen::MatrixXd x(static_cast<Eigen::Index>(n), 3);
        x.col(0) = rise(t_s, n, a);
        x.col(1) = rise(t_s, n, b);
        x.col(2).setOnes();
        return project(x, yv, beta);
    };
    const auto grid = log_grid(3.0 * dt, 5.0 * span, kGridPoints);
    Eigen::VectorXd beta;
    double best = INFINITY;
    std::vector<double> start{std::log(grid[0]), std::log(grid[1])};
    for (std::size_t i = 0; i < grid.size(); ++i) {
        for (std::size_t j = i + 1; j < grid.size(); ++j) {
            const double r = rss_at(grid[i], grid[j], beta);
            if (r < best) best = r, start = {std::log(grid[i]), std::log(grid[j])};
        }
    }
    // The simplex stays on the grid's range: beyond it two exponentials become a line and a constant with
    // amplitudes that grow without bound while the residual hardly changes.
    const auto on_grid = [&](double x) { return std::clamp(std::exp(x), grid.front(), grid.back()); };
    const auto nm = nelder_mead(
        [&](const std::vector<double>& x) {
            Eigen::VectorXd b;
            return rss_at(on_grid(x[0]), on_grid(x[1]), b);
        },
        start, {0.2, 0.2}, kRefineEvaluations);
    double a = on_grid(nm.x[0]), b = on_grid(nm.x[1]);
    TwoExponentials out;
    out.rss = rss_at(a, b, beta);
    double ca = beta(0), cb = beta(1);
    if (a > b) std::swap(a, b), std::swap(ca, cb);
    out.t_s = a;
    out.c1_counts = ca;
    out.t2_s = b;
    out.c3_counts = cb;
    out.c2_counts = beta(2);
    return out;
}

ExponentialAndSine fit_exponential_and_sine(const std::vector<double>& t_s, const std::vector<double>& y, std::size_t n) {
    const Eigen::Map<const Eigen::VectorXd> yv(y.data(), static_cast<Eigen::Index>(n));
    const double dt = (t_s[n - 1] - t_s[0]) / static_cast<double>(n - 1);
    const double span = t_s[n - 1] - t_s[0];
    auto rss_at = [&](double tau, double period, Eigen::VectorXd& beta) {
        Eigen::MatrixXd x(static_cast<Eigen::Index>(n), 4);
        x.col(0) = rise(t_s, n, tau);
        x.col(1).setOnes();
        for (std::size_t i = 0; i < n; ++i) {
            const double w = 2.0 * std::numbers::pi * t_s[i] / period;
            x(static_cast<Eigen::Index>(i), 2) = std::sin(w);
            x(static_cast<Eigen::Index>(i), 3) = std::cos(w);
        }
        return project(x, yv, beta);
    };
    const auto taus = log_grid(3.0 * dt, 5.0 * span, 12);
    // Periods from 8 samples to half the span: a single cycle is a drift shape that eq. 1 competes for, and a
    // periodic effect is told from drift only by its repeating (gap-method E2: three cycles are recommended).
    const auto periods = log_grid(8.0 * dt, 0.5 * span, 4 * kGridPoints);
    Eigen::VectorXd beta;
    double best = INFINITY;
    std::vector<double> start{std::log(taus[0]), std::log(periods[0])};
    for (double tau : taus) {
        for (double p : periods) {
            const double r = rss_at(tau, p, beta);
            if (r < best) best = r, start = {std::log(tau), std::log(p)};
        }
    }
    // Within the grid's range: a period beyond the span is a slope with an unbounded amplitude.
    const auto tau_of = [&](double x) { return std::clamp(std::exp(x), taus.front(), taus.back()); };
    const auto period_of = [&](double x) { return std::clamp(std::exp(x), periods.front(), periods.back()); };
    const auto nm = nelder_mead(
        [&](const std::vector<double>& x) {
            Eigen::VectorXd b;
            return rss_at(tau_of(x[0]), period_of(x[1]), b);
        },
        start, {0.2, 0.02}, kRefineEvaluations);
    ExponentialAndSine out;
    out.t_s = tau_of(nm.x[0]);
    out.period_s = period_of(nm.x[1]);
    out.rss = rss_at(out.t_s, out.period_s, beta);
    out.c1_counts = beta(0);
    out.c2_counts = beta(1);
    // a sin w + b cos w = R sin(w + phi)
    out.amplitude_counts = std::hypot(beta(2), beta(3));
    out.phase_rad = std::atan2(beta(3), beta(2));
    return out;
}

}  // namespace driftlab::host::gap
