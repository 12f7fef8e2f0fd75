// Nelder-Mead simplex minimisation (Lagarias et al., SIAM J. Optim. 9(1), 1998: reflection 1, expansion 2,
// contraction 1/2, shrink 1/2) for the candidate fits, which have <= 3 parameters and noisy objectives.
// docs/gap.md §Candidate fits.
#pragma once

#include <functional>
#include <vector>

namespace driftlab::host::gap {

struct NelderMeadResult {
    std::vector<double> x;
    double value = 0.0;
    int evaluations = 0;
};

/// Minimises `f` from `start` with initial steps `step` (one per coordinate), within `max_evaluations`.
NelderMeadResult nelder_mead(const std::function<double(const std::vector<double>&)>& f, const std::vector<double>& start,
                             const std::vector<double>& step, int max_evaluations);

}  // namespace driftlab::host::gap
