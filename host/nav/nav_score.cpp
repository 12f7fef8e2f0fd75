#include "host/nav/nav_score.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "host/stats/chi_square.hpp"

namespace driftlab::host::nav {

NeesBand nees_band(int dof) { return {stats::chi_square_quantile(0.025, dof), stats::chi_square_quantile(0.975, dof)}; }

namespace {

// The last row at or before `t_s`, or none past the log's end.
std::optional<std::size_t> row_at(const std::vector<double>& t, double t_s) {
    if (t.empty() || t_s > t.back() + 1e-9) return std::nullopt;
    const auto it = std::upper_bound(t.begin(), t.end(), t_s + 1e-9);
    return static_cast<std::size_t>(it - t.begin()) - 1;
}

}  // namespace

NavScore score(const NavRun& run, const NavTruth& truth, const std::vector<double>& at_s) {
    NavScore out;
    out.at_s = at_s;
    const std::vector<double>& t = run.t_s;
    const std::size_t last = t.size() - 1;
    out.duration_s = t.back() - t.front();
    for (std::size_t i = 1; i < t.size(); ++i)
        out.distance_m += std::hypot(truth.x(i) - truth.x(i - 1), truth.y(i) - truth.y(i - 1));
    out.nees_dof = run.heading_only ? 1 : 3;
    const NeesBand band = nees_band(out.nees_dof);
    for (const Track& tr : run.tracks) {
        VariantScore v;
        v.name = tr.name;
        const auto heading_error = [&](std::size_t i) { return std::abs(tr.heading_deg[i] - truth.heading_deg(i)); };
        const auto position_error = [&](std::size_t i) {
            return run.heading_only ? NAN : std::hypot(tr.x_m[i] - truth.x(i), tr.y_m[i] - truth.y(i));
        };
        for (const double a : at_s) {
            const auto i = row_at(t, t.front() + a);
            v.heading_error_deg.push_back(i ? heading_error(*i) : NAN);
            v.position_error_m.push_back(i ? position_error(*i) : NAN);
        }
        v.final_heading_error_deg = heading_error(last);
        v.final_position_error_m = position_error(last);
        if (out.duration_s > 0.0) v.heading_drift_deg_per_min = v.final_heading_error_deg / (out.duration_s / 60.0);
        if (out.distance_m > 0.0) v.position_error_pct = 100.0 * v.final_position_error_m / out.distance_m;
        std::size_t inside = 0, epochs = 0;
        for (const double e : tr.nees) {
            if (!std::isfinite(e)) continue;
            ++epochs;
            inside += (e >= band.low && e <= band.high) ? 1 : 0;
        }
        if (epochs > 0) v.nees_inside_fraction = static_cast<double>(inside) / static_cast<double>(epochs);
        out.variants.push_back(v);
    }
    return out;
}

double heading_drift_at_stops(const Track& track, const std::vector<double>& t_s) {
    double turned = 0.0, stood = 0.0;
    for (const Stop& s : track.stops) {
        const auto a = row_at(t_s, s.from_s), b = row_at(t_s, s.to_s);
        if (!a || !b || *b <= *a) continue;
        turned += track.heading_deg[*b] - track.heading_deg[*a];
        stood += s.to_s - s.from_s;
    }
    return stood > 0.0 ? turned / (stood / 60.0) : NAN;
}

}  // namespace driftlab::host::nav
