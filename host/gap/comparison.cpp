// Real-vs-replicate comparison; see comparison.hpp.
#include "host/gap/comparison.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace driftlab::host::gap {

namespace {

// A cell on which every replicate agrees exactly would give an infinite z for the smallest difference.
double sd_floor(double mean) { return 1e-9 + 1e-6 * std::abs(mean); }

// Monte Carlo test: the real log exceeds the k-th smallest of R exchangeable null values with probability
// (R + 1 - k)/(R + 1), so the level-alpha bound is order statistic k = (1 - alpha)(R + 1), interpolated. (The
// plain sample quantile, k = 1 + (1 - alpha)(R - 1), flags about 2 alpha at R = 20.) With R + 1 < 1/alpha no bound
// reaches alpha: the largest null value is the best there is.
double monte_carlo_bound(std::vector<double> null, double alpha) {
    std::sort(null.begin(), null.end());
    const auto r_count = static_cast<double>(null.size());
    const double pos = (1.0 - alpha) * (r_count + 1.0) - 1.0;  // 0-based
    const auto lo = static_cast<std::size_t>(std::clamp(std::floor(pos), 0.0, r_count - 1.0));
    const auto hi = std::min(lo + 1, null.size() - 1);
    return null[lo] + std::clamp(pos - static_cast<double>(lo), 0.0, 1.0) * (null[hi] - null[lo]);
}

}  // namespace

Comparison compare(const std::vector<double>& real, const Eigen::MatrixXd& replicates, double alpha,
                   const std::vector<double>* cell_floor) {
    const Eigen::Index r_count = replicates.rows();
    const Eigen::Index cells = replicates.cols();
    Comparison cmp;
    cmp.z.resize(static_cast<std::size_t>(cells));
    cmp.sim_mean.resize(static_cast<std::size_t>(cells));
    cmp.sim_sd.resize(static_cast<std::size_t>(cells));
    cmp.loo_z.resize(r_count, cells);
    for (Eigen::Index j = 0; j < cells; ++j) {
        const auto col = replicates.col(j);
        const double s1 = col.sum();
        const double s2 = col.squaredNorm();
        const double n = static_cast<double>(r_count);
        const double mean = s1 / n;
        const auto u = static_cast<std::size_t>(j);
        const double least = cell_floor ? (*cell_floor)[u] : 0.0;
        const double sd = std::max({std::sqrt(std::max(0.0, (s2 - n * mean * mean) / (n - 1))), sd_floor(mean), least});
        cmp.sim_mean[u] = mean;
        cmp.sim_sd[u] = sd;
        cmp.z[u] = (real[u] - mean) / sd;
        for (Eigen::Index r = 0; r < r_count; ++r) {
            const double x = col(r);
            const double m = (s1 - x) / (n - 1);
            const double v = std::max(0.0, (s2 - x * x - (n - 1) * m * m) / (n - 2));
            cmp.loo_z(r, j) = (x - m) / std::max({std::sqrt(v), sd_floor(m), least});
        }
    }
    std::vector<double> maxima(static_cast<std::size_t>(r_count));
    for (Eigen::Index r = 0; r < r_count; ++r)
        maxima[static_cast<std::size_t>(r)] = cmp.loo_z.row(r).cwiseAbs().maxCoeff();
    cmp.threshold = monte_carlo_bound(maxima, alpha);
    return cmp;
}

double gap_score(const Comparison& cmp, const std::vector<Cell>& layout, const CellFilter& keep) {
    double real = 0.0, null = 0.0;
    std::size_t count = 0;
    for (std::size_t j = 0; j < layout.size(); ++j) {
        if (!keep(layout[j])) continue;
        ++count;
        real += cmp.z[j] * cmp.z[j];
        null += cmp.loo_z.col(static_cast<Eigen::Index>(j)).squaredNorm();
    }
    if (count == 0) return 1.0;
    // Replicates that all agree on every cell (a lossless link): the log's own mean z^2, 1 where it agrees too.
    if (null <= 0.0) return real > 0.0 ? real / static_cast<double>(count) : 1.0;
    return real / (null / static_cast<double>(cmp.loo_z.rows()));
}

double gap_score_threshold(const Comparison& cmp, const std::vector<Cell>& layout, const CellFilter& keep,
                           double alpha) {
    const Eigen::Index r_count = cmp.loo_z.rows();
    std::vector<double> per_replicate(static_cast<std::size_t>(r_count), 0.0);
    std::size_t count = 0;
    for (std::size_t j = 0; j < layout.size(); ++j) {
        if (!keep(layout[j])) continue;
        ++count;
        for (Eigen::Index r = 0; r < r_count; ++r)
            per_replicate[static_cast<std::size_t>(r)] +=
                cmp.loo_z(r, static_cast<Eigen::Index>(j)) * cmp.loo_z(r, static_cast<Eigen::Index>(j));
    }
    double mean = 0.0;
    for (double v : per_replicate) mean += v / static_cast<double>(r_count);
    if (count == 0 || mean <= 0.0) return 1.0;
    for (double& v : per_replicate) v /= mean;
    return monte_carlo_bound(per_replicate, alpha);
}

std::vector<LocatedCell> locate(const std::vector<double>& real, const Comparison& cmp,
                                const std::vector<Cell>& layout) {
    std::vector<LocatedCell> out;
    for (std::size_t j = 0; j < layout.size(); ++j) {
        const double diff = real[j] - cmp.sim_mean[j];
        if (std::abs(cmp.z[j]) <= cmp.threshold || std::abs(diff) <= layout[j].margin) continue;
        LocatedCell c;
        c.index = j;
        c.real = real[j];
        c.sim_mean = cmp.sim_mean[j];
        c.z = cmp.z[j];
        c.difference = diff;
        c.ratio = layout[j].log_scale ? std::exp(diff) : std::numeric_limits<double>::quiet_NaN();
        const double half = 1.96 * cmp.sim_sd[j];
        c.interval_low = layout[j].log_scale ? std::exp(diff - half) : diff - half;
        c.interval_high = layout[j].log_scale ? std::exp(diff + half) : diff + half;
        out.push_back(c);
    }
    std::sort(out.begin(), out.end(),
              [](const LocatedCell& a, const LocatedCell& b) { return std::abs(a.z) > std::abs(b.z); });
    return out;
}

}  // namespace driftlab::host::gap
