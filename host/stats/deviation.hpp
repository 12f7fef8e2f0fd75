// The Allan-family deviations driftlab computes and the curve they produce (docs/allan.md §1).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "host/stats/phase_record.hpp"

namespace driftlab::host::stats {

/// Which statistic. All are deviations (square roots of the variances), of the rate, at tau = m * tau0.
enum class Deviation : std::uint8_t {
    adev,   ///< Allan deviation, non-overlapping (NIST SP 1065 eq. 7)
    oadev,  ///< overlapping Allan deviation (SP 1065 eq. 11)
    mdev,   ///< modified Allan deviation (SP 1065 eq. 14)
    hdev,   ///< Hadamard deviation, non-overlapping (SP 1065 eq. 17)
    ohdev,  ///< overlapping Hadamard deviation (SP 1065 eq. 18)
};

/// Parses "adev", "oadev", "mdev", "hdev", "ohdev"; throws std::invalid_argument otherwise.
Deviation parse_deviation(std::string_view name);
std::string_view deviation_name(Deviation dev);

/// Order of the phase difference the statistic is built on: 2 for Allan/modified, 3 for Hadamard.
int difference_order(Deviation dev);
/// True for the overlapping and modified estimators (stride 1), false for stride m.
bool is_overlapping(Deviation dev);
/// Stable32's divisor of the largest averaging factor (see stable32_max_factor in tau_grid.hpp).
int stable32_factor_divisor(Deviation dev);

/// One deviation evaluated on a grid. Parallel arrays, one entry per averaging factor that had >= 1 term.
struct DeviationCurve {
    Deviation type = Deviation::oadev;
    std::vector<std::int64_t> m;          ///< averaging factor
    std::vector<double> tau_s;            ///< m * tau0 [s]
    std::vector<double> dev;              ///< the deviation [data unit] (rate unit)
    std::vector<std::int64_t> n;          ///< terms summed (Stable32's "#"), after skipping gap-touching terms
    std::vector<std::int64_t> n_skipped;  ///< terms a gap-free record of the same length would have had extra
};

/// Evaluates `type` at each averaging factor in `ms` (ascending), O(N) per factor, the factors shared among
/// `threads` threads (the same digits however many). Factors that leave no term are left out of the curve.
DeviationCurve compute_deviation(const PhaseRecord& record, Deviation type, std::span<const std::int64_t> ms,
                                 int threads = 1);

}  // namespace driftlab::host::stats
