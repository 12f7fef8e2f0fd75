// Lone values: single samples far from both neighbours while the neighbours agree, the mark of a corrupt row (a bus
// error's 0x7FFF, a mangled digit, a value from another column) or of an impulse, rather than of motion or a step. One
// such row in a plain table had given a "converged" eq. 1 fit with C2 = 4e296 and an Allan deviation 1e298 at every
// tau, unremarked. docs/analysis.md §1.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace driftlab::host::stats {

/// How far from both neighbours a lone value sits, in robust standard deviations of the first differences.
inline constexpr double kLoneFactor = 10.0;
/// The part of the sample-to-sample variance (the sum of squared first differences; twice AVAR at tau0 times the
/// count) from which lone values are worth a warning: they then inflate the white-noise level by 5 % or more.
inline constexpr double kLoneShare = 0.1;

struct LoneValues {
    std::vector<std::size_t> indices;  ///< in the series, in order
    double variance_share = 0.0;       ///< their first differences' part of the sum of squared first differences
};

/// The lone values of `x`: |x_k - x_k-1| and |x_k+1 - x_k| both above kLoneFactor times the robust scale of the first
/// differences (1.4826 times their median absolute value; where that is 0, as on a series that mostly repeats one
/// code, the step: the smallest nonzero difference other than x_k's own two, at most `code`, and `code` when there is
/// none), and |x_k+1 - x_k-1| below half the smaller of them. `code` is the values' quantum where it is known (one
/// converter code for counts), else 0: then a series constant but for x_k has no step, and any departure is lone,
/// while two departing rows measure each other. The first and last samples have one neighbour, and a step could not
/// be told from a lone value there: they are never lone. Safe for any finite values, up to the largest double.
LoneValues lone_values(const std::vector<double>& x, double code = 0.0);

/// A warning naming when (from `t_s`) and what the lone values of `x` are, and the --exclude windows that leave them
/// out (each end the shortest number between the row and its neighbour), when they carry kLoneShare or more of its
/// sample-to-sample variance; none otherwise. `code` as for lone_values().
std::optional<std::string> lone_values_warning(const std::vector<double>& t_s, const std::vector<double>& x,
                                               double code = 0.0);

/// The same for lone values already found (`found` = lone_values(x, code)), for a caller that keeps them too.
std::optional<std::string> lone_values_warning(const std::vector<double>& t_s, const std::vector<double>& x,
                                               const LoneValues& found);

}  // namespace driftlab::host::stats
