// Samples onto a uniform grid with explicit gaps (docs/allan.md §7).
#include "host/stats/uniform_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "host/stats/median.hpp"

namespace driftlab::host::stats {

double median_spacing_s(std::span<const double> t_s) {
    if (t_s.size() < 2) return 0.0;
    std::vector<double> d(t_s.size() - 1);
    for (std::size_t i = 0; i + 1 < t_s.size(); ++i) d[i] = t_s[i + 1] - t_s[i];
    return median(std::move(d));
}

double mean_spacing_s(std::span<const double> t_s) {
    return t_s.size() < 2 ? 0.0 : (t_s.back() - t_s.front()) / static_cast<double>(t_s.size() - 1);
}

bool spacing_agrees(double a_s, double b_s) { return std::abs(a_s / b_s - 1.0) <= kSpacingTolerance; }

bool period_agrees(std::span<const double> t_s, double period_s) {
    // The mean first: it is two rows' arithmetic where the median sorts a copy of every spacing.
    return t_s.size() < 2 || spacing_agrees(mean_spacing_s(t_s), period_s) ||
           spacing_agrees(median_spacing_s(t_s), period_s);
}

double grid_period_s(std::span<const double> t_s) {
    const double median = median_spacing_s(t_s);
    const double mean = mean_spacing_s(t_s);
    return mean > 2.0 * median ? mean : median;
}

std::string spacing_text(std::span<const double> t_s) {
    char text[120];
    std::snprintf(text, sizeof text, "%g s apart (median; mean %g s)", median_spacing_s(t_s), mean_spacing_s(t_s));
    return text;
}

std::optional<std::string> tau0_disagreement(std::span<const double> t_s, double tau0_s) {
    if (period_agrees(t_s, tau0_s)) return std::nullopt;
    char text[60];
    std::snprintf(text, sizeof text, "--tau0 %g s", tau0_s);
    return std::string(text) + ", but the time column's rows are " + spacing_text(t_s);
}

UniformSeries to_uniform_grid(std::span<const double> t_s, std::span<const double> values, double tau0_s) {
    if (t_s.size() != values.size()) throw std::invalid_argument("uniform grid: times and values differ in length");
    if (!(tau0_s > 0.0) || !std::isfinite(tau0_s)) throw std::invalid_argument("uniform grid: tau0 must be > 0");
    UniformSeries out;
    out.tau0_s = tau0_s;
    if (t_s.empty()) return out;
    out.t0_s = t_s.front();
    std::vector<std::size_t> slot(t_s.size(), 0);
    for (std::size_t k = 1; k < t_s.size(); ++k) {
        const double nominal = std::round((t_s[k] - out.t0_s) / tau0_s);
        if (!(nominal <= 20.0 * static_cast<double>(t_s.size()) + 20.0)) {
            throw std::invalid_argument("uniform grid: the times span far more slots than samples (tau0 too small?)");
        }
        slot[k] = std::max(slot[k - 1] + 1, static_cast<std::size_t>(std::max(nominal, 0.0)));
        // Jitter moves a sample one slot at most; further, the rows come faster than tau0.
        const double late = static_cast<double>(slot[k]) - nominal;
        if (late >= 2.0) {
            ++out.packed;
            out.most_late = std::max(out.most_late, static_cast<std::size_t>(late));
        }
    }
    if (slot.back() > 20 * t_s.size() + 20) {
        throw std::invalid_argument("uniform grid: the times span far more slots than samples (tau0 too small?)");
    }
    out.values.assign(slot.back() + 1, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t k = 0; k < t_s.size(); ++k) out.values[slot[k]] = values[k];
    out.missing = out.values.size() - t_s.size();
    return out;
}

}  // namespace driftlab::host::stats
