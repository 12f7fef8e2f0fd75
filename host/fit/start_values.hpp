// Automatic start for the eq. 1 fit: no user guess, rising or falling drifts alike. docs/analysis.md §2.2.
//
// Given T, eq. 1 is linear in C1 and C2, so the best C1, C2 and residual sum of squares follow from a 2x2
// least-squares solve (variable projection). The profile RSS(T) is scanned on a log grid of T from a
// quarter of a block to 100x the record, on equal-count block means of the data (at most 200 blocks,
// so the cost is O(N) + O(grid x blocks)), and refined by golden-section search on log T around the best
// grid point. The sign of C1 comes out of the linear solve, so rising and falling drifts need nothing special.
#pragma once

#include <vector>

#include "host/fit/drift_model.hpp"

namespace driftlab::host::fit {

struct StartValues {
    DriftParameters parameters;
    double block_rss = 0.0;       ///< weighted RSS of the block means at the start
    bool t_at_upper_end = false;  ///< best T is the grid's largest: no curvature seen (straight or flat data)
    bool t_at_lower_end = false;  ///< best T is the grid's smallest: a step at the start, nothing after
};

/// Start values for t_s (strictly increasing, >= 2 distinct times) and y of equal length.
StartValues automatic_start(const std::vector<double>& t_s, const std::vector<double>& y);

/// The least-squares C1 and C2 of eq. 1 at a fixed T (the variable-projection profile, every sample alike).
DriftParameters amplitudes_at(const std::vector<double>& t_s, const std::vector<double>& y, double t_const_s);

}  // namespace driftlab::host::fit
