// Lag-1 autocorrelation noise identification (docs/allan.md §5).
#include "host/stats/noise_id.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace driftlab::host::stats {
namespace {

// Removes the least-squares polynomial of degree `deg` (<= 2) in the sample index. On a uniform grid
// symmetric about its centre, 1, t and t^2 - mean(t^2) are orthogonal, so the fit is three projections, O(n).
// Double precision suffices: only the sign and size of the lag-1 correlation matter.
void detrend(std::vector<double>& v, int deg) {
    const std::size_t n = v.size();
    const double half = 0.5 * static_cast<double>(n - 1);
    double t2_mean = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) - half;
        t2_mean += t * t;
    }
    t2_mean /= static_cast<double>(n);
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, n1 = 0.0, n2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) - half;
        const double p2 = t * t - t2_mean;
        s0 += v[i];
        s1 += v[i] * t;
        n1 += t * t;
        s2 += v[i] * p2;
        n2 += p2 * p2;
    }
    const double a0 = s0 / static_cast<double>(n);
    const double a1 = (deg >= 1 && n1 > 0.0) ? s1 / n1 : 0.0;
    const double a2 = (deg >= 2 && n2 > 0.0) ? s2 / n2 : 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) - half;
        v[i] = v[i] - a0 - a1 * t - a2 * (t * t - t2_mean);
    }
}

// Lag-1 autocorrelation about the mean (Riley-Greenhall eq. 2); NaN for a constant series.
double lag1_autocorrelation(const std::vector<double>& v) {
    double mean = 0.0;
    for (double x : v) mean += x;
    mean /= static_cast<double>(v.size());
    double num = 0.0;
    double den = 0.0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const double d = v[i] - mean;
        den += d * d;
        if (i + 1 < v.size()) num += d * (v[i + 1] - mean);
    }
    if (den <= 0.0) return std::nan("");
    return num / den;
}

// Detrends the decimated (phase) or averaged (rate) series and differences it until it looks stationary.
std::optional<NoiseId> identify(std::vector<double> v, InputKind kind, int dmin, int dmax) {
    if (v.size() < kNoiseIdMinPoints) return std::nullopt;
    // Phase: remove frequency offset and drift; rate: remove drift.
    detrend(v, kind == InputKind::phase ? 2 : 1);
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
            // Within the types the variance converges for (Allan, dmax 2: -2..2; Hadamard, dmax 3: -4..2): near
            // r1 = -1/2 (white PM) rho = r1 / (1 + r1) runs off to minus infinity on a short series, and rate input
            // differenced dmax times goes below the range; both are read as the nearest type in range, as Stable32
            // does.
            id.alpha = std::clamp(static_cast<int>(-std::lround(2.0 * rho)) - 2 * d + phase_offset, 2 - 2 * dmax, 2);
            return id;
        }
        for (std::size_t i = 0; i + 1 < v.size(); ++i) v[i] = v[i + 1] - v[i];
        v.pop_back();
        if (v.size() < 2) return std::nullopt;
    }
}

}  // namespace

std::optional<NoiseId> autocorr_noise_id(std::span<const double> samples, InputKind kind, std::int64_t m, int dmin,
                                         int dmax) {
    if (m < 1) return std::nullopt;
    const auto mu = static_cast<std::size_t>(m);
    std::vector<double> v;
    if (kind == InputKind::phase) {
        for (std::size_t i = 0; i < samples.size(); i += mu) v.push_back(samples[i]);
    } else {
        for (std::size_t b = 0; b + mu <= samples.size(); b += mu) {
            long double s = 0.0L;
            for (std::size_t i = b; i < b + mu; ++i) s += samples[i];
            v.push_back(static_cast<double>(s / static_cast<long double>(mu)));
        }
    }
    return identify(std::move(v), kind, dmin, dmax);
}

std::optional<NoiseId> autocorr_noise_id(const PhaseRecord& record, std::int64_t m, int dmax) {
    const Segment s = record.longest_segment();
    if (s.size() < 2 || m < 1) return std::nullopt;
    const auto mu = static_cast<std::size_t>(m);
    const double* x = record.scaled_phase().data() + s.begin;
    std::vector<double> v;
    v.reserve(s.size() / mu + 1);
    if (record.kind() == InputKind::phase) {
        for (std::size_t i = 0; i < s.size(); i += mu) v.push_back(x[i]);
    } else {
        // The mean of m rate samples is a phase difference over m steps (divided by m tau0, a scale the
        // autocorrelation ignores): O(N/m) instead of O(N).
        for (std::size_t i = 0; i + mu < s.size(); i += mu) v.push_back(x[i + mu] - x[i]);
    }
    return identify(std::move(v), record.kind(), 0, dmax);
}

}  // namespace driftlab::host::stats
