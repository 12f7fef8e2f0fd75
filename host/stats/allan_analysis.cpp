// Deviation + noise identification + EDF + confidence interval per tau (docs/allan.md §§3-5).
#include "host/stats/allan_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "host/stats/noise_id.hpp"
#include "host/util/parallel_for.hpp"

namespace driftlab::host::stats {
namespace {

// White FM (alpha 0) is the assumption when no tau could be identified at all: angle random walk for a gyro.
constexpr int kDefaultAlpha = 0;

// Terms one gap-free segment of `samples` phase samples contributes (mirrors allan.cpp / hadamard.cpp).
double segment_terms(Deviation type, double samples, double m) {
    switch (type) {
    case Deviation::adev: return std::floor((samples - 1.0) / m) - 1.0;
    case Deviation::oadev: return samples - 2.0 * m;
    case Deviation::mdev: return samples - 3.0 * m + 1.0;
    case Deviation::hdev: return std::floor((samples - 1.0) / m) - 2.0;
    case Deviation::ohdev: return samples - 3.0 * m;
    }
    return 0.0;
}

// Pools independent segment estimates s_k with weights n_k / sum n: var = sum (n_k / n)^2 * 2 sigma^4 / edf_k.
double pooled_edf(const PhaseRecord& record, Deviation type, int alpha, double m) {
    double n_total = 0.0;
    double inv = 0.0;
    for (const Segment& s : record.segments()) {
        const double samples = static_cast<double>(s.size());
        const double n = segment_terms(type, samples, m);
        if (n < 1.0) continue;
        const double edf = edf_for(type, alpha, m, samples);
        n_total += n;
        inv += n * n / edf;
    }
    if (n_total <= 0.0 || inv <= 0.0) return 1.0;
    return n_total * n_total / inv;
}

}  // namespace

std::vector<std::int64_t> analysis_factors(const PhaseRecord& record, Deviation type, const TauGridOptions& grid) {
    const std::int64_t max_m = stable32_max_factor(record.size(), stable32_factor_divisor(type));
    return averaging_factors(grid, max_m);
}

AnalysedCurve analyse_deviation(const PhaseRecord& record, Deviation type, std::span<const std::int64_t> ms,
                                double confidence, int threads) {
    AnalysedCurve out;
    out.curve = compute_deviation(record, type, ms, threads);
    const int dmax = difference_order(type);
    std::vector<std::optional<NoiseId>> ids(out.curve.m.size());
    parallel_for(ids.size(), threads, [&](std::size_t i) { ids[i] = autocorr_noise_id(record, out.curve.m[i], dmax); });
    int alpha = kDefaultAlpha;
    bool have_alpha = false;
    for (std::size_t i = 0; i < out.curve.m.size(); ++i) {
        const std::int64_t m = out.curve.m[i];
        const std::optional<NoiseId>& id = ids[i];
        if (id) {
            alpha = id->alpha;
            have_alpha = true;
        }
        const double edf = record.has_gaps()
                               ? pooled_edf(record, type, alpha, static_cast<double>(m))
                               : edf_for(type, alpha, static_cast<double>(m), static_cast<double>(record.size()));
        const ConfidenceInterval ci = confidence_interval(out.curve.dev[i], edf, confidence);
        out.alpha.push_back(alpha);
        out.alpha_identified.push_back(id.has_value() && have_alpha);
        out.edf.push_back(edf);
        out.ci_low.push_back(ci.low);
        out.ci_high.push_back(ci.high);
    }
    return out;
}

}  // namespace driftlab::host::stats
