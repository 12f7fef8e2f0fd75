// Hadamard variance on phase, overlapping or not (NIST SP 1065 eqs. 17-18; docs/allan.md §1): third
// differences, insensitive to a linear frequency drift, hence its use beside the Allan variance for a gyro
// still warming up. Same gap handling as allan.hpp.
#pragma once

#include <cstdint>

#include "host/stats/phase_record.hpp"
#include "host/stats/term_sum.hpp"

namespace driftlab::host::stats {

/// Sum of (x[i+3m] - 3 x[i+2m] + 3 x[i+m] - x[i])^2 over i = every sample (overlapping) or every m-th sample
/// from each segment's start. Terms per segment of L samples: L - 3m, resp. floor((L-1)/m) - 2.
TermSum hadamard_terms(const PhaseRecord& record, std::int64_t m, bool overlapping);

}  // namespace driftlab::host::stats
