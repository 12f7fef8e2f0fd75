// Samples onto a uniform grid with explicit gaps (docs/allan.md §7).
#include "host/stats/uniform_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace driftlab::host::stats {

double median_spacing_s(std::span<const double> t_s) {
    if (t_s.size() < 2) return 0.0;
    std::vector<double> d(t_s.size() - 1);
    for (std::size_t i = 0; i + 1 < t_s.size(); ++i) d[i] = t_s[i + 1] - t_s[i];
    const auto mid = d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2);
    std::nth_element(d.begin(), mid, d.end());
    return *mid;
}

UniformSeries to_uniform_grid(std::span<const double> t_s, std::span<const double> values, double tau0_s) {
    if (t_s.size() != values.size()) throw std::invalid_argument("uniform grid: times and values differ in length");
    if (!(tau0_s > 0.0) || !std::isfinite(tau0_s)) throw std::invalid_argument("uniform grid: tau0 must be > 0");
    UniformSeries out;
    out.tau0_s = tau0_s;
    if (t_s.empty()) return out;
    out.t0_s = t_s.front();
    const double span_slots = std::round((t_s.back() - t_s.front()) / tau0_s);
    if (!(span_slots >= 0.0) || span_slots > 20.0 * static_cast<double>(t_s.size()) + 20.0) {
        throw std::invalid_argument("uniform grid: the times span far more slots than samples (tau0 too small?)");
    }
    out.values.assign(static_cast<std::size_t>(span_slots) + 1, std::numeric_limits<double>::quiet_NaN());
    std::vector<bool> filled(out.values.size(), false);
    for (std::size_t k = 0; k < t_s.size(); ++k) {
        const double slot = std::round((t_s[k] - out.t0_s) / tau0_s);
        const auto i = static_cast<std::size_t>(std::clamp(slot, 0.0, span_slots));
        if (filled[i]) {
            ++out.collisions;
            continue;
        }
        filled[i] = true;
        out.values[i] = values[k];
    }
    out.missing = static_cast<std::size_t>(std::count(filled.begin(), filled.end(), false));
    return out;
}

}  // namespace driftlab::host::stats
