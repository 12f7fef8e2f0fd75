// Nelder-Mead simplex minimisation for the candidate fits, which have <= 3 parameters and noisy objectives:
// NLopt's LN_NELDERMEAD (the Debian package libnlopt-dev) with a fixed evaluation budget and no tolerance, since a
// simulated objective's noise would stop a tolerance test at random. docs/gap.md §Candidates.
#pragma once

#include <functional>
#include <vector>

namespace driftlab::host::stats {

struct NelderMeadResult {
    std::vector<double> x;
    double value = 0.0;
    int evaluations = 0;
};

/// Minimises `f` from `start` with initial steps `step` (one per coordinate), within `max_evaluations`. A non-finite
/// value counts as worse than any finite one; an exception thrown by `f` stops the search and is rethrown.
NelderMeadResult nelder_mead(const std::function<double(const std::vector<double>&)>& f,
                             const std::vector<double>& start, const std::vector<double>& step, int max_evaluations);

}  // namespace driftlab::host::stats
