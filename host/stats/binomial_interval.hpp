// Exact (Clopper-Pearson) confidence interval of a binomial proportion, for rates measured on few trials
// (the gap benchmark's false-positive rate, docs/gap.md).
#pragma once

#include <cstddef>

namespace driftlab::host::stats {

struct ProportionInterval {
    double lower = 0.0;
    double upper = 1.0;
};

/// Clopper-Pearson interval of k successes in n trials at confidence `level` (e.g. 0.95): the Beta quantiles
/// B(alpha/2; k, n-k+1) and B(1-alpha/2; k+1, n-k), with 0 and 1 at k = 0 and k = n. Throws
/// std::invalid_argument when n == 0, k > n or level is outside (0, 1).
ProportionInterval clopper_pearson(std::size_t k, std::size_t n, double level = 0.95);

}  // namespace driftlab::host::stats
