// Lag-1 autocorrelation noise identification (docs/allan.md §5).
#include "host/stats/noise_id.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <vector>

namespace driftlab::host::stats {
namespace {

// Removes the least-squares polynomial of degree `deg` in the sample index (scaled to [-1, 1] for conditioning).
void detrend(std::vector<double>& v, int deg) {
    const auto n = static_cast<Eigen::Index>(v.size());
    Eigen::MatrixXd a(n, deg + 1);
    const double half = 0.5 * static_cast<double>(n - 1);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double t = half > 0.0 ? (static_cast<double>(i) - half) / half : 0.0;
        double p = 1.0;
        for (int k = 0; k <= deg; ++k, p *= t) a(i, k) = p;
    }
    const Eigen::Map<Eigen::VectorXd> y(v.data(), n);
    const Eigen::VectorXd coef = a.colPivHouseholderQr().solve(y);
    const Eigen::VectorXd residual = y - a * coef;
    for (Eigen::Index i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = residual(i);
}

// Lag-1 autocorrelation about the mean (Riley-Greenhall eq. 2); NaN for a constant series.
double lag1_autocorrelation(const std::vector<double>& v) {
    long double mean = 0.0L;
    for (double x : v) mean += x;
    mean /= static_cast<long double>(v.size());
    long double num = 0.0L;
    long double den = 0.0L;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const long double d = v[i] - mean;
        den += d * d;
        if (i + 1 < v.size()) num += d * (v[i + 1] - mean);
    }
    if (den <= 0.0L) return std::nan("");
    return static_cast<double>(num / den);
}

}  // namespace

std::optional<NoiseId> autocorr_noise_id(std::span<const double> samples, InputKind kind, std::int64_t m,
                                         int dmin, int dmax) {
    if (m < 1) return std::nullopt;
    const auto mu = static_cast<std::size_t>(m);
    std::vector<double> v;
    if (kind == InputKind::phase) {
        for (std::size_t i = 0; i < samples.size(); i += mu) v.push_back(samples[i]);
        if (v.size() < kNoiseIdMinPoints) return std::nullopt;
        detrend(v, 2);  // frequency offset and drift
    } else {
        for (std::size_t b = 0; b + mu <= samples.size(); b += mu) {
            long double s = 0.0L;
            for (std::size_t i = b; i < b + mu; ++i) s += samples[i];
            v.push_back(static_cast<double>(s / static_cast<long double>(mu)));
        }
        if (v.size() < kNoiseIdMinPoints) return std::nullopt;
        detrend(v, 1);  // frequency drift
    }
    const int phase_offset = kind == InputKind::phase ? 2 : 0;
    for (int d = 0;; ++d) {
        const double r1 = lag1_autocorrelation(v);
        if (std::isnan(r1)) return std::nullopt;
        const double rho = r1 / (1.0 + r1);
        if (d >= dmin && (rho < 0.25 || d >= dmax)) {
            NoiseId id;
            id.rho = rho;
            id.differences = d;
            id.alpha_estimate = -2.0 * (rho + d) + phase_offset;
            id.alpha = static_cast<int>(-std::lround(2.0 * rho)) - 2 * d + phase_offset;
            return id;
        }
        for (std::size_t i = 0; i + 1 < v.size(); ++i) v[i] = v[i + 1] - v[i];
        v.pop_back();
        if (v.size() < 2) return std::nullopt;
    }
}

std::optional<NoiseId> autocorr_noise_id(const PhaseRecord& record, std::int64_t m, int dmax) {
    const Segment s = record.longest_segment();
    if (s.size() < 2) return std::nullopt;
    const double* x = record.phase().data();
    if (record.kind() == InputKind::phase) {
        return autocorr_noise_id(std::span<const double>(x + s.begin, s.size()), InputKind::phase, m, 0, dmax);
    }
    std::vector<double> rate(s.size() - 1);
    for (std::size_t i = 0; i + 1 < s.size(); ++i) rate[i] = x[s.begin + i + 1] - x[s.begin + i];
    return autocorr_noise_id(rate, InputKind::rate, m, 0, dmax);
}

}  // namespace driftlab::host::stats
