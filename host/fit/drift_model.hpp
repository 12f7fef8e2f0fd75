// The turn-on drift model, paper eq. 1: eps(t) = C1 (1 - exp(-t/T)) + C2, with t the time since power-on
// (its least-squares problem for the solver: drift_functor.hpp). docs/analysis.md §2.
#pragma once

#include <cmath>

namespace driftlab::host::fit {

/// Eq. 1 parameters. C1 and C2 in the unit of the data (A/D counts for a canonical log), T in seconds.
struct DriftParameters {
    double c1 = 0.0;   ///< amplitude of the transient [counts]
    double c2 = 0.0;   ///< value at power-on [counts]; settles at C1 + C2
    double t_s = 1.0;  ///< time constant T [s]
};

/// Eq. 1 at time t [s].
inline double drift_model(const DriftParameters& p, double t_s) { return p.c1 * -std::expm1(-t_s / p.t_s) + p.c2; }

}  // namespace driftlab::host::fit
