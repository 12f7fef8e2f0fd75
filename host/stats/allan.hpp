// Allan variances on phase: overlapping, non-overlapping and modified (NIST SP 1065 eqs. 7, 11, 14;
// docs/allan.md §1). Each returns the raw sum of squared terms at one averaging factor m, O(N) per m; gap
// handling comes from the record's segments (a term is used only inside one segment).
#pragma once

#include <cstdint>

#include "host/stats/phase_record.hpp"
#include "host/stats/term_sum.hpp"

namespace driftlab::host::stats {

/// Sum of (x[i+2m] - 2 x[i+m] + x[i])^2 over i = every sample (overlapping) or every m-th sample from each
/// segment's start (non-overlapping). Terms per gap-free segment of L samples: L - 2m, resp. floor((L-1)/m) - 1.
TermSum allan_terms(const PhaseRecord& record, std::int64_t m, bool overlapping);

/// Sum over j of (sum_{i=j}^{j+m-1} x[i+2m] - 2 x[i+m] + x[i])^2, by a sliding update in extended precision.
/// Terms per segment of L samples: L - 3m + 1.
TermSum modified_allan_terms(const PhaseRecord& record, std::int64_t m);

}  // namespace driftlab::host::stats
