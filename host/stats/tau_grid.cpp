// Averaging-factor grids (docs/allan.md §3).
#include "host/stats/tau_grid.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace driftlab::host::stats {

TauGrid parse_tau_grid(std::string_view name) {
    if (name == "octave") return TauGrid::octave;
    if (name == "log") return TauGrid::log;
    if (name == "all") return TauGrid::all;
    if (name == "stable32") return TauGrid::stable32_all;
    throw std::invalid_argument("unknown tau grid '" + std::string(name) + "' (expected octave, log, all, stable32)");
}

std::vector<std::int64_t> averaging_factors(const TauGridOptions& options, std::int64_t max_m) {
    std::vector<std::int64_t> ms;
    if (max_m < 1) return ms;
    switch (options.grid) {
    case TauGrid::octave:
        for (std::int64_t m = 1; m <= max_m; m *= 2) ms.push_back(m);
        break;
    case TauGrid::log: {
        if (options.points_per_decade < 1) throw std::invalid_argument("points per decade must be >= 1");
        const double step = 1.0 / options.points_per_decade;
        for (int k = 0;; ++k) {
            const auto m = static_cast<std::int64_t>(std::llround(std::pow(10.0, k * step)));
            if (m > max_m) break;
            if (ms.empty() || m > ms.back()) ms.push_back(m);
        }
        break;
    }
    case TauGrid::all:
        for (std::int64_t m = 1; m <= max_m; ++m) ms.push_back(m);
        break;
    case TauGrid::stable32_all:
        if (options.step_divisor < 1) throw std::invalid_argument("step divisor must be >= 1");
        // Stable32 stops strictly below its bound (see stable32_max_factor).
        for (std::int64_t m = 1; m < max_m; m += 1 + m / options.step_divisor) ms.push_back(m);
        break;
    }
    return ms;
}

std::int64_t stable32_max_factor(std::size_t phase_samples, int divisor) {
    if (phase_samples < 2 || divisor < 1) return 0;
    return static_cast<std::int64_t>((phase_samples - 1) / static_cast<std::size_t>(divisor));
}

}  // namespace driftlab::host::stats
