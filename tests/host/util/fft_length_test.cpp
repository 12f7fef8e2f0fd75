// 2-3-5 transform lengths against a brute-force search by trial division.
#include <gtest/gtest.h>

#include "host/util/fft_length.hpp"

namespace driftlab::host {
namespace {

bool only_two_three_five(std::size_t m) {
    for (std::size_t p : {2u, 3u, 5u})
        while (m % p == 0) m /= p;
    return m == 1;
}

TEST(FftLength, KnownLengths) {
    EXPECT_EQ(smooth_length_at_most(1499), 1458u);  // 2 * 3^6
    EXPECT_EQ(smooth_length_at_most(1500), 1500u);
    EXPECT_EQ(smooth_length_at_most(7), 6u);
    EXPECT_EQ(smooth_length_at_least(1459), 1500u);
    EXPECT_EQ(smooth_length_at_least(7), 8u);
    EXPECT_EQ(smooth_length_at_least(1), 1u);
    // The lag-correlation transform of a 180 000-sample part to lag 22 500: 2^2 3^4 5^4, where a power of two >= 2n is
    // 524 288.
    EXPECT_EQ(smooth_length_at_least(202500), 202500u);
}

TEST(FftLength, TheNearestSmoothLengthEitherSideOfEveryLengthUpTo5000) {
    for (std::size_t n = 1; n <= 5000; ++n) {
        std::size_t below = n, above = n;
        while (!only_two_three_five(below)) --below;
        while (!only_two_three_five(above)) ++above;
        ASSERT_EQ(smooth_length_at_most(n), below) << n;
        ASSERT_EQ(smooth_length_at_least(n), above) << n;
    }
}

}  // namespace
}  // namespace driftlab::host
