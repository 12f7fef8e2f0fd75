// 2-3-5 transform lengths; see fft_length.hpp.
#include "host/util/fft_length.hpp"

#include <algorithm>
#include <limits>

namespace driftlab::host {

namespace {

// f(m) for every m = 2^a 3^b 5^c <= limit.
template <class F>
void for_each_smooth(std::size_t limit, F&& f) {
    for (std::size_t p2 = 1; p2 <= limit; p2 *= 2)
        for (std::size_t p3 = p2; p3 <= limit; p3 *= 3)
            for (std::size_t p5 = p3; p5 <= limit; p5 *= 5) f(p5);
}

}  // namespace

std::size_t smooth_length_at_most(std::size_t n) {
    std::size_t best = 1;
    for_each_smooth(n, [&](std::size_t m) { best = std::max(best, m); });
    return best;
}

std::size_t smooth_length_at_least(std::size_t n) {
    // Some power of two in [n, 2n) qualifies, so every candidate is below 2n.
    std::size_t best = std::numeric_limits<std::size_t>::max();
    for_each_smooth(2 * std::max<std::size_t>(n, 1), [&](std::size_t m) {
        if (m >= n) best = std::min(best, m);
    });
    return best;
}

}  // namespace driftlab::host
