// Variable-projection fits of the deterministic candidates; see mean_shapes.hpp.
//
// For fixed time constants (and period) the amplitudes are linear least squares; the constant column is handled by
// centring every column and the data, so only the small Gram matrix of the centred columns is solved. The grids
// share their dot products (a column's with the data and with the other columns is computed once per grid value,
// not once per grid pair), which keeps a 360 000-sample log's grid search to a fraction of a second.
#include "host/gap/mean_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Dense>

#include "host/gap/whittle.hpp"
#include "host/stats/nelder_mead.hpp"

namespace driftlab::host::gap {

namespace {

constexpr int kGridPoints = 24;
constexpr int kRefineEvaluations = 120;
// The second time constant is at least twice the first (gap-method E1: die 1-5 min, package/board 10-60 min).
// Closer ones are the derivative of one exponential, fitted with huge opposite amplitudes.
constexpr double kMinRatio = 2.0;

std::vector<double> log_grid(double lo, double hi, int points) {
    std::vector<double> g(static_cast<std::size_t>(points));
    for (int i = 0; i < points; ++i) g[static_cast<std::size_t>(i)] = lo * std::pow(hi / lo, i / double(points - 1));
    return g;
}

// A column centred on its mean, and that mean.
struct Column {
    Eigen::VectorXd centred;
    double mean = 0.0;
};

Column centre(Eigen::VectorXd v) {
    const double m = v.mean();
    v.array() -= m;
    return {std::move(v), m};
}

Column rise(const std::vector<double>& t_s, std::size_t n, double tau_s) {
    Eigen::VectorXd v(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) v(static_cast<Eigen::Index>(i)) = -std::expm1(-t_s[i] / tau_s);
    return centre(std::move(v));
}

std::pair<Column, Column> sine_cosine(const std::vector<double>& t_s, std::size_t n, double period_s) {
    Eigen::VectorXd s(static_cast<Eigen::Index>(n)), c(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) {
        const double w = 2.0 * std::numbers::pi * t_s[i] / period_s;
        s(static_cast<Eigen::Index>(i)) = std::sin(w);
        c(static_cast<Eigen::Index>(i)) = std::cos(w);
    }
    return {centre(std::move(s)), centre(std::move(c))};
}

// Least squares of the centred data on centred columns from their Gram matrix `g` and their products with the
// data `b`: the coefficients, and the residual sum of squares yy - b'beta (for ranking a grid; the refinement
// computes the residual itself).
double solve(const Eigen::MatrixXd& g, const Eigen::VectorXd& b, double yy, Eigen::VectorXd& beta) {
    beta = g.ldlt().solve(b);
    if (!beta.allFinite()) beta = g.completeOrthogonalDecomposition().solve(b);
    return std::max(0.0, yy - b.dot(beta));
}

// The data, centred.
struct Data {
    Eigen::VectorXd centred;
    double mean = 0.0;
    double yy = 0.0;
};

Data centred_data(const std::vector<double>& y, std::size_t n) {
    Data d;
    d.centred = Eigen::Map<const Eigen::VectorXd>(y.data(), static_cast<Eigen::Index>(n));
    d.mean = d.centred.mean();
    d.centred.array() -= d.mean;
    d.yy = d.centred.squaredNorm();
    return d;
}

// The centred products of `count` columns generated a block of samples at a time, so that no column is held whole
// (a grid of 24 columns of an hour at 100 Hz had been 69 MB): the columns' means from a first pass, then per block
// the centred columns' Gram matrix and their products with the centred data. `fill(first, block)` writes samples
// first .. first + block.rows() - 1 of every column into `block`, one column each.
struct CentredProducts {
    Eigen::MatrixXd gram;
    Eigen::VectorXd with_data;
};

template <class Fill>
CentredProducts centred_products(std::size_t n, Eigen::Index count, const Data& data, Fill fill) {
    constexpr std::size_t kBlock = 4096;
    Eigen::MatrixXd block;
    const auto each_block = [&](auto use) {
        for (std::size_t first = 0; first < n; first += kBlock) {
            block.resize(static_cast<Eigen::Index>(std::min(kBlock, n - first)), count);
            fill(first, block);
            use(first);
        }
    };
    Eigen::RowVectorXd means = Eigen::RowVectorXd::Zero(count);
    each_block([&](std::size_t) { means += block.colwise().sum(); });
    means /= static_cast<double>(n);
    CentredProducts p{Eigen::MatrixXd::Zero(count, count), Eigen::VectorXd::Zero(count)};
    each_block([&](std::size_t first) {
        block.rowwise() -= means;
        p.gram.selfadjointView<Eigen::Lower>().rankUpdate(block.transpose());
        p.with_data += block.transpose() * data.centred.segment(static_cast<Eigen::Index>(first), block.rows());
    });
    p.gram = p.gram.selfadjointView<Eigen::Lower>();
    return p;
}

}  // namespace

std::vector<double> eq1_and_steps_residual(const std::vector<double>& t_s, const std::vector<double>& y,
                                           std::size_t cut1, std::size_t cut2) {
    const std::size_t n = y.size();
    const Data data = centred_data(y, n);
    const auto step = [&](std::size_t cut) {
        Eigen::VectorXd v(static_cast<Eigen::Index>(n));
        for (std::size_t k = 0; k < n; ++k) v(static_cast<Eigen::Index>(k)) = k >= cut ? 1.0 : 0.0;
        return centre(std::move(v));
    };
    const Column s1 = step(cut1), s2 = step(cut2);
    Eigen::VectorXd best;
    const double span = t_s.back() - t_s.front();
    for (double tau = 0.003 * span; tau < 30.0 * span; tau *= 1.2) {
        const Column r = rise(t_s, n, tau);
        Eigen::Matrix3d g;
        g << r.centred.squaredNorm(), r.centred.dot(s1.centred), r.centred.dot(s2.centred), 0.0,
            s1.centred.squaredNorm(), s1.centred.dot(s2.centred), 0.0, 0.0, s2.centred.squaredNorm();
        g = g.selfadjointView<Eigen::Upper>();
        Eigen::VectorXd beta;
        solve(g,
              Eigen::Vector3d(r.centred.dot(data.centred), s1.centred.dot(data.centred), s2.centred.dot(data.centred)),
              data.yy, beta);
        Eigen::VectorXd e = data.centred - beta(0) * r.centred - beta(1) * s1.centred - beta(2) * s2.centred;
        if (best.size() == 0 || e.squaredNorm() < best.squaredNorm()) best = std::move(e);
    }
    return {best.data(), best.data() + best.size()};
}

TwoExponentials fit_two_exponentials(const std::vector<double>& t_s, const std::vector<double>& y, std::size_t n) {
    const Data data = centred_data(y, n);
    const double dt = (t_s[n - 1] - t_s[0]) / static_cast<double>(n - 1);
    const double span = t_s[n - 1];
    const auto grid = log_grid(3.0 * dt, 5.0 * span, kGridPoints);
    const CentredProducts p =
        centred_products(n, static_cast<Eigen::Index>(grid.size()), data, [&](std::size_t first, Eigen::MatrixXd& b) {
            for (Eigen::Index c = 0; c < b.cols(); ++c)
                for (Eigen::Index k = 0; k < b.rows(); ++k)
                    b(k, c) =
                        -std::expm1(-t_s[first + static_cast<std::size_t>(k)] / grid[static_cast<std::size_t>(c)]);
        });
    double best = INFINITY;
    std::vector<double> start{std::log(grid[0]), std::log(grid[1])};
    Eigen::VectorXd beta;
    for (Eigen::Index i = 0; i < p.gram.rows(); ++i) {
        for (Eigen::Index j = i + 1; j < p.gram.rows(); ++j) {
            const double gi = grid[static_cast<std::size_t>(i)], gj = grid[static_cast<std::size_t>(j)];
            if (gj < kMinRatio * gi) continue;
            const Eigen::Matrix2d g{{p.gram(i, i), p.gram(i, j)}, {p.gram(i, j), p.gram(j, j)}};
            const double r = solve(g, Eigen::Vector2d(p.with_data(i), p.with_data(j)), data.yy, beta);
            if (r < best) best = r, start = {std::log(gi), std::log(gj)};
        }
    }
    auto rss_at = [&](double a, double b, Eigen::VectorXd& coef, double& level) {
        if (std::max(a, b) < kMinRatio * std::min(a, b)) return std::numeric_limits<double>::infinity();
        const Column ca = rise(t_s, n, a), cb = rise(t_s, n, b);
        Eigen::Matrix2d g;
        g << ca.centred.squaredNorm(), ca.centred.dot(cb.centred), 0.0, cb.centred.squaredNorm();
        g(1, 0) = g(0, 1);
        solve(g, Eigen::Vector2d(ca.centred.dot(data.centred), cb.centred.dot(data.centred)), data.yy, coef);
        level = data.mean - coef(0) * ca.mean - coef(1) * cb.mean;
        return (data.centred - coef(0) * ca.centred - coef(1) * cb.centred).squaredNorm();
    };
    // The simplex stays on the grid's range: beyond it two exponentials become a line and a constant with
    // amplitudes that grow without bound while the residual hardly changes.
    const auto on_grid = [&](double x) { return std::clamp(std::exp(x), grid.front(), grid.back()); };
    double level = 0.0;
    const auto nm = stats::nelder_mead(
        [&](const std::vector<double>& x) {
            Eigen::VectorXd c;
            double l;
            return rss_at(on_grid(x[0]), on_grid(x[1]), c, l);
        },
        start, {0.2, 0.2}, kRefineEvaluations);
    double a = on_grid(nm.x[0]), b = on_grid(nm.x[1]);
    TwoExponentials out;
    out.rss = rss_at(a, b, beta, level);
    double ca = beta(0), cb = beta(1);
    if (a > b) std::swap(a, b), std::swap(ca, cb);
    out.t_s = a;
    out.c1_counts = ca;
    out.t2_s = b;
    out.c3_counts = cb;
    out.c2_counts = level;
    return out;
}

ExponentialAndSine fit_exponential_and_sine(const std::vector<double>& t_s, const std::vector<double>& y,
                                            std::size_t n) {
    const Data data = centred_data(y, n);
    const double dt = (t_s[n - 1] - t_s[0]) / static_cast<double>(n - 1);
    const double span = t_s[n - 1] - t_s[0];
    const auto taus = log_grid(3.0 * dt, 5.0 * span, 12);
    // Periods from 8 samples to half the span: a single cycle is a drift shape that eq. 1 competes for, and a
    // periodic effect is told from drift only by its repeating (gap-method E2: three cycles are recommended).
    const auto periods = log_grid(8.0 * dt, 0.5 * span, 4 * kGridPoints);
    std::vector<Column> rises;
    std::vector<double> rise_data, rise_rise;
    for (double tau : taus) {
        rises.push_back(rise(t_s, n, tau));
        rise_data.push_back(rises.back().centred.dot(data.centred));
        rise_rise.push_back(rises.back().centred.squaredNorm());
    }
    // Columns (rise, sin, cos) of the centred data: the Gram matrix and the products with the data.
    auto fill = [](Eigen::Matrix3d& g, Eigen::Vector3d& b, const Column& r, const Column& s, const Column& c,
                   const Eigen::VectorXd& yc) {
        g << r.centred.squaredNorm(), r.centred.dot(s.centred), r.centred.dot(c.centred), 0.0, s.centred.squaredNorm(),
            s.centred.dot(c.centred), 0.0, 0.0, c.centred.squaredNorm();
        g(1, 0) = g(0, 1), g(2, 0) = g(0, 2), g(2, 1) = g(1, 2);
        b << r.centred.dot(yc), s.centred.dot(yc), c.centred.dot(yc);
    };
    double best = INFINITY;
    std::vector<double> start{std::log(taus[0]), std::log(periods[0])};
    Eigen::VectorXd beta;
    for (double p : periods) {
        const auto [s, c] = sine_cosine(t_s, n, p);
        const double ss = s.centred.squaredNorm(), sc = s.centred.dot(c.centred), cc = c.centred.squaredNorm();
        const double sy = s.centred.dot(data.centred), cy = c.centred.dot(data.centred);
        for (std::size_t i = 0; i < taus.size(); ++i) {
            Eigen::Matrix3d g;
            g << rise_rise[i], rises[i].centred.dot(s.centred), rises[i].centred.dot(c.centred), 0.0, ss, sc, 0.0, 0.0,
                cc;
            g(1, 0) = g(0, 1), g(2, 0) = g(0, 2), g(2, 1) = g(1, 2);
            const double r = solve(g, Eigen::Vector3d(rise_data[i], sy, cy), data.yy, beta);
            if (r < best) best = r, start = {std::log(taus[i]), std::log(p)};
        }
    }
    auto rss_at = [&](double tau, double period, Eigen::VectorXd& coef, double& level) {
        const Column r = rise(t_s, n, tau);
        const auto [s, c] = sine_cosine(t_s, n, period);
        Eigen::Matrix3d g;
        Eigen::Vector3d b;
        fill(g, b, r, s, c, data.centred);
        solve(g, b, data.yy, coef);
        level = data.mean - coef(0) * r.mean - coef(1) * s.mean - coef(2) * c.mean;
        return (data.centred - coef(0) * r.centred - coef(1) * s.centred - coef(2) * c.centred).squaredNorm();
    };
    // Within the grid's range: a period beyond the span is a slope with an unbounded amplitude.
    const auto tau_of = [&](double x) { return std::clamp(std::exp(x), taus.front(), taus.back()); };
    const auto period_of = [&](double x) { return std::clamp(std::exp(x), periods.front(), periods.back()); };
    const auto nm = stats::nelder_mead(
        [&](const std::vector<double>& x) {
            Eigen::VectorXd coef;
            double level;
            return rss_at(tau_of(x[0]), period_of(x[1]), coef, level);
        },
        start, {0.2, 0.02}, kRefineEvaluations);
    ExponentialAndSine out;
    out.t_s = tau_of(nm.x[0]);
    out.period_s = period_of(nm.x[1]);
    double level = 0.0;
    out.rss = rss_at(out.t_s, out.period_s, beta, level);
    out.c1_counts = beta(0);
    out.c2_counts = level;
    // a sin w + b cos w = R sin(w + phi)
    out.amplitude_counts = std::hypot(beta(1), beta(2));
    out.phase_rad = std::atan2(beta(2), beta(1));
    return out;
}

Eigen::MatrixXd eq1_tangent(const std::vector<double>& t_s, double tau_s) {
    Eigen::MatrixXd x(static_cast<Eigen::Index>(t_s.size()), 3);
    for (std::size_t k = 0; k < t_s.size(); ++k) {
        const double u = t_s[k] / tau_s, e = std::exp(-u);
        x.row(static_cast<Eigen::Index>(k)) << 1.0, e, u * e;
    }
    return x;
}

Eigen::MatrixXd eq1_tangent_basis(const std::vector<double>& t_s, double tau_s) {
    return orthonormal_basis(eq1_tangent(t_s, tau_s));
}

}  // namespace driftlab::host::gap
