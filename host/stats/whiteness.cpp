// Whiteness tests; see whiteness.hpp and docs/analysis.md §3.
#include "host/stats/whiteness.hpp"

#include <algorithm>
#include <cmath>

#include "host/util/error.hpp"
#include "host/util/format_number.hpp"

namespace driftlab::host::stats {
namespace {

constexpr std::size_t kMinSamples = 10;

std::vector<double> normalised(const std::vector<double>& r) {
    std::vector<double> rho(r.size());
    for (std::size_t d = 0; d < r.size(); ++d) rho[d] = r[d] / r[0];
    return rho;
}

/// Eq. 3/4 per sequence, averaged over the sequences (Fig. 4).
void ensemble(const std::vector<double>& w, double sample_period_s, const WhitenessOptions& options,
              WhitenessResult& out) {
    const std::size_t n = w.size();
    std::size_t len = static_cast<std::size_t>(std::llround(options.sequence_length_s / sample_period_s));
    std::size_t m = std::max<std::size_t>(1, options.sequences);
    len = std::max<std::size_t>(len, 2);
    if (len > n) {
        out.adaptation = "residual (" + std::to_string(n) + " samples) shorter than one sequence of " +
                         format_double(options.sequence_length_s) + " s: one sequence of the whole residual";
        len = n;
        m = 1;
    } else if (m * len > n) {
        const std::size_t fit = n / len;
        out.adaptation = "residual holds " + std::to_string(fit) + " sequences of " +
                         format_double(options.sequence_length_s) + " s, not " + std::to_string(m) + ": used " +
                         std::to_string(fit);
        m = fit;
    }
    out.sequences_used = m;
    out.sequence_samples = len;
    out.sequence_length_s = static_cast<double>(len) * sample_period_s;
    // A sequence is a whole number of samples (two at least): at a coarse sample period its length moves. A move
    // below a tenth of a per cent (times at 1.7e9 s, 0.1 s apart, are 0.09999990463 s apart) is no adaptation, and
    // four digits show any larger one (the full digits had printed 49.99995231628418 s).
    if (out.adaptation.empty() &&
        std::fabs(out.sequence_length_s - options.sequence_length_s) > 1e-3 * options.sequence_length_s)
        out.adaptation = "sequences of " + significant(out.sequence_length_s, 4) + " s (" + std::to_string(len) +
                         " samples of " + significant(sample_period_s, 4) +
                         " s), the nearest whole number of samples to " + format_double(options.sequence_length_s) +
                         " s";
    out.ensemble_rho.assign(len, 0.0);
    std::size_t used = 0;
    for (std::size_t s = 0; s < m; ++s) {
        const std::size_t start = m == 1 ? 0 : s * (n - len) / (m - 1);
        const std::vector<double> seq(w.begin() + static_cast<std::ptrdiff_t>(start),
                                      w.begin() + static_cast<std::ptrdiff_t>(start + len));
        const std::vector<double> r = biased_autocovariance(seq, len - 1);
        if (!(r[0] > 0.0)) continue;  // a constant stretch (e.g. quantised to one code) has no shape
        for (std::size_t d = 0; d < len; ++d) out.ensemble_rho[d] += r[d] / r[0];
        ++used;
    }
    if (used == 0) throw UsageError("whiteness: every sequence of the residual is constant");
    for (auto& v : out.ensemble_rho) v /= static_cast<double>(used);
    out.sequences_used = used;
    out.bound = 2.0 / std::sqrt(static_cast<double>(used * len));
    std::size_t inside = 0;
    for (std::size_t d = 1; d < len; ++d) inside += std::fabs(out.ensemble_rho[d]) <= out.bound;
    out.fraction_inside = len > 1 ? static_cast<double>(inside) / static_cast<double>(len - 1) : 1.0;
}

}  // namespace

WhitenessResult test_whiteness(const std::vector<double>& residual, double sample_period_s,
                               const WhitenessOptions& options) {
    const std::size_t n = residual.size();
    if (n < kMinSamples)
        throw UsageError("whiteness: need at least " + std::to_string(kMinSamples) + " residual samples, got " +
                         std::to_string(n));
    if (!(sample_period_s > 0.0)) throw UsageError("whiteness: sample period must be > 0");
    // Autocorrelations do not depend on scale; a power of two that brings the largest value near 1 changes no bit
    // of them, and keeps the FFT's squares from underflowing (1e-170) or overflowing (1e200) to a constant series.
    double largest = 0.0;
    for (double v : residual) largest = std::max(largest, std::fabs(v));
    std::vector<double> w = residual;
    if (largest > 0.0 && std::isfinite(largest)) {
        int exponent = 0;
        std::frexp(largest, &exponent);
        for (double& v : w) v = std::ldexp(v, -exponent);
    }
    WhitenessResult out;
    out.sample_period_s = sample_period_s;
    ensemble(w, sample_period_s, options, out);

    const std::size_t h = options.ljung_box_lags ? std::min(options.ljung_box_lags, n - 1) : default_ljung_box_lags(n);
    const std::vector<double> r = biased_autocovariance(w, std::max(h, n / 4));
    if (!(r[0] > 0.0)) throw UsageError("whiteness: the residual is identically zero");
    const std::vector<double> rho = normalised(r);
    out.ljung_box = ljung_box(rho, n, h);
    out.autocorrelation_time = integrated_autocorrelation_time(rho);
    const std::size_t keep = std::max(h, out.autocorrelation_time.window) + 1;
    out.rho.assign(rho.begin(), rho.begin() + static_cast<std::ptrdiff_t>(std::min(keep, rho.size())));
    out.white = out.ljung_box.p_value >= options.alpha;
    return out;
}

}  // namespace driftlab::host::stats
