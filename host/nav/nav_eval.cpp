#include "host/nav/nav_eval.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace driftlab::host::nav {

double quantile(std::vector<double> values, double q) {
    values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
                 values.end());
    if (values.empty()) return NAN;
    std::sort(values.begin(), values.end());
    const double h = q * static_cast<double>(values.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(h));
    const std::size_t hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (h - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

EvalSummary summarise(const std::vector<EvalRun>& runs) {
    EvalSummary out;
    out.runs = runs.size();
    if (runs.empty()) return out;
    out.at_s = runs.front().score.at_s;
    for (std::size_t v = 0; v < runs.front().score.variants.size(); ++v) {
        EvalVariant e;
        e.name = runs.front().score.variants[v].name;
        const auto over_runs = [&](const std::function<double(const VariantScore&)>& get) {
            std::vector<double> xs;
            for (const EvalRun& r : runs) xs.push_back(get(r.score.variants[v]));
            return xs;
        };
        for (std::size_t k = 0; k < out.at_s.size(); ++k) {
            const auto h = over_runs([k](const VariantScore& s) { return s.heading_error_deg[k]; });
            const auto p = over_runs([k](const VariantScore& s) { return s.position_error_m[k]; });
            e.heading_error_deg.push_back(quantile(h, 0.5));
            e.heading_error_deg_p95.push_back(quantile(h, 0.95));
            e.position_error_m.push_back(quantile(p, 0.5));
            e.position_error_m_p95.push_back(quantile(p, 0.95));
        }
        const auto drift = over_runs([](const VariantScore& s) { return s.heading_drift_deg_per_min; });
        const auto pct = over_runs([](const VariantScore& s) { return s.position_error_pct; });
        e.heading_drift_deg_per_min = quantile(drift, 0.5);
        e.heading_drift_deg_per_min_p95 = quantile(drift, 0.95);
        e.position_error_pct = quantile(pct, 0.5);
        e.position_error_pct_p95 = quantile(pct, 0.95);
        e.nees_inside_fraction = quantile(over_runs([](const VariantScore& s) { return s.nees_inside_fraction; }), 0.5);
        out.variants.push_back(e);
    }
    return out;
}

}  // namespace driftlab::host::nav
