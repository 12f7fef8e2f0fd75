// Hadamard variance on phase (docs/allan.md §1): third differences, per gap-free segment.
#include "host/stats/hadamard.hpp"

#include <cstddef>

namespace driftlab::host::stats {

TermSum hadamard_terms(const PhaseRecord& record, std::int64_t m, bool overlapping) {
    TermSum out;
    if (m < 1) return out;
    const auto mu = static_cast<std::size_t>(m);
    const std::size_t stride = overlapping ? 1 : mu;
    const double* x = record.scaled_phase().data();
    for (const Segment& s : record.segments()) {
        if (s.size() < 3 * mu + 1) continue;
        double acc[2] = {0.0, 0.0};
        std::size_t k = 0;
        for (std::size_t i = s.begin; i + 3 * mu < s.end; i += stride, ++k) {
            const double d = x[i + 3 * mu] - 3.0 * x[i + 2 * mu] + 3.0 * x[i + mu] - x[i];
            acc[k & 1] += d * d;
        }
        out.sum_sq += static_cast<long double>(acc[0]) + acc[1];
        out.n += static_cast<std::int64_t>(k);
    }
    return out;
}

}  // namespace driftlab::host::stats
