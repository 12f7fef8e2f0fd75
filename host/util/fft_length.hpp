// Transform lengths whose prime factors are 2, 3 and 5: the FFT is fast on them, and they lie far closer to a
// series' own length than a power of two does (at most 8 % away above 1000 points, against up to 100 %).
#pragma once

#include <cstddef>

namespace driftlab::host {

/// Largest length <= n whose prime factors are 2, 3 and 5 (1 for n < 2).
std::size_t smooth_length_at_most(std::size_t n);

/// Smallest length >= n whose prime factors are 2, 3 and 5.
std::size_t smooth_length_at_least(std::size_t n);

}  // namespace driftlab::host
