// Averaging-factor grids for the Allan-family deviations (docs/allan.md §3). tau = m * tau0.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace driftlab::host::stats {

/// Which averaging factors m to evaluate.
enum class TauGrid : std::uint8_t {
    octave,        ///< m = 1, 2, 4, 8, ...
    log,           ///< about `points_per_decade` log-spaced m per decade (distinct integers)
    all,           ///< every m: O(N^2) in total, for short records only
    stable32_all,  ///< Stable32's dense "all tau" list: m_{k+1} = m_k + 1 + floor(m_k / step_divisor)
};

/// Parses "octave", "log", "all", "stable32"; throws std::invalid_argument otherwise.
TauGrid parse_tau_grid(std::string_view name);

struct TauGridOptions {
    TauGrid grid = TauGrid::octave;
    int points_per_decade = 10;      ///< for TauGrid::log
    std::int64_t step_divisor = 53;  ///< for TauGrid::stable32_all (Stable32 files use 42, 53 or 71)
};

/// Averaging factors 1 <= m <= max_m, ascending, per the grid.
std::vector<std::int64_t> averaging_factors(const TauGridOptions& options, std::int64_t max_m);

/// Largest m Stable32 evaluates for a record of `phase_samples` phase samples: floor((N-1)/divisor) with
/// divisor 4 for overlapping/modified statistics and 5 for non-overlapping ADEV/HDEV, so that every tau keeps
/// enough terms. Stable32's dense list stops strictly below that bound; octave grids include it.
std::int64_t stable32_max_factor(std::size_t phase_samples, int divisor);

}  // namespace driftlab::host::stats
