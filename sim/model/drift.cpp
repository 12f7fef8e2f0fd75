// Eq. 1 of the paper; see drift.hpp.
#include "sim/model/drift.hpp"

#include <cmath>

namespace driftlab::sim {

double Drift::at_counts(double t_s) const {
    // expm1 keeps the small-t rise exact instead of cancelling 1 - exp(-t/T).
    return -params_.c1_counts * std::expm1(-t_s / params_.tau_s) + params_.c2_counts;
}

}  // namespace driftlab::sim
