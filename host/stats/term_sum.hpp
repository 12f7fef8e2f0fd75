// TermSum: the sum of squared phase differences one deviation at one averaging factor is built from.
#pragma once

#include <cstdint>

namespace driftlab::host::stats {

/// Sum of squared terms and their count; the deviation's normalisation is applied by compute_deviation.
struct TermSum {
    long double sum_sq = 0.0L;  ///< sum of squared phase differences [(data unit * s)^2]
    std::int64_t n = 0;         ///< terms summed
};

}  // namespace driftlab::host::stats
