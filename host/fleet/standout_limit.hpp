// How far from its batch a board must lie to stand out (docs/fleet.md §Standing out). The robust z-score of the
// largest of n boards drawn from one normal distribution is large by chance: its scale, the median absolute
// deviation of n values, is itself uncertain (at n = 20 a cut of 3.5 names a board in 6 % of such batches for one
// parameter, and in 80 % for 24 parameters). The limit is therefore the value that max |z| over the batch exceeds
// with probability kFalseStandout / parameters for normal draws — Bonferroni over the parameters judged — found by
// simulation with a fixed seed, so that a batch without outliers names a board in at most kFalseStandout of fleets.
#pragma once

#include <cstddef>

namespace driftlab::host::fleet {

/// The median absolute deviation times this is the standard deviation of normal scatter.
inline constexpr double kMadToSigma = 1.4826;

/// The share of outlier-free batches in which some board is named nonetheless.
inline constexpr double kFalseStandout = 0.05;

/// The robust z-score limit for a parameter known on `boards` boards (>= 3), `parameters` parameters judged in all.
double standout_limit(std::size_t boards, std::size_t parameters);

}  // namespace driftlab::host::fleet
