// Q8 helpers (fixed_point.hpp) against double-precision references.
#include "driftlab/proto/fixed_point.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

namespace driftlab {
namespace proto {
namespace {

TEST(FixedPoint, CountsToQ8ScalesBy256) {
  EXPECT_EQ(counts_to_q8(0), 0);
  EXPECT_EQ(counts_to_q8(1), 256);
  EXPECT_EQ(counts_to_q8(1023), 1023 * 256);
  EXPECT_EQ(counts_to_q8(-512), -512 * 256);
}

TEST(FixedPoint, DivToQ8RoundsToNearestLikeDoubleReference) {
  // Numerators and denominators of the firmware's use: sums of up to 64 ten-bit codes, windows 1..64.
  std::mt19937 rng(42);
  std::uniform_int_distribution<int32_t> num_dist(-64 * 1023, 64 * 1023);
  std::uniform_int_distribution<int32_t> den_dist(1, 64);
  for (int trial = 0; trial < 200000; ++trial) {
    const int32_t num = num_dist(rng);
    const int32_t den = den_dist(rng);
    const double exact = static_cast<double>(num) * 256.0 / static_cast<double>(den);
    // std::round rounds halves away from zero, the documented rule.
    ASSERT_EQ(div_to_q8(num, den), static_cast<int32_t>(std::round(exact))) << num << "/" << den;
  }
}

TEST(FixedPoint, DivToQ8HalvesGoAwayFromZero) {
  // 1/512 count is exactly half of one Q8 step.
  EXPECT_EQ(div_to_q8(1, 512), 1);
  EXPECT_EQ(div_to_q8(-1, 512), -1);
  EXPECT_EQ(div_to_q8(1, 513), 0);
}

TEST(FixedPoint, Q8RoundToCountsMatchesDoubleReference) {
  for (int32_t q8 = -300000; q8 <= 300000; ++q8) {
    ASSERT_EQ(q8_round_to_counts(q8), static_cast<int32_t>(std::round(q8 / 256.0))) << q8;
  }
}

TEST(FixedPoint, ConstantsDescribeQ8) {
  EXPECT_EQ(kQ8One, 1 << kQ8FractionBits);
  EXPECT_EQ(kQ8FractionBits, 8);
}

}  // namespace
}  // namespace proto
}  // namespace driftlab
