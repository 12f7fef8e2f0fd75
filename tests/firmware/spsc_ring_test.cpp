// SpscRing properties against a std::deque model: FIFO order, exact capacity, full/empty refusals, and index
// wrap-around far beyond 256 operations.
#include "firmware/core/spsc_ring.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <random>

namespace driftlab {
namespace fw {
namespace {

template <uint8_t Capacity>
void check_random_operations(uint32_t seed, int operations, int push_percent) {
  SpscRing<uint32_t, Capacity> ring;
  std::deque<uint32_t> model;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> percent(0, 99);
  uint32_t next_value = 0;
  for (int i = 0; i < operations; ++i) {
    if (percent(rng) < push_percent) {
      const bool accepted = ring.push(next_value);
      ASSERT_EQ(accepted, model.size() < Capacity) << "operation " << i;
      if (accepted) {
        model.push_back(next_value);
      }
      ++next_value;
    } else {
      uint32_t out = 0xDEADBEEF;
      const bool got = ring.pop(&out);
      ASSERT_EQ(got, !model.empty()) << "operation " << i;
      if (got) {
        ASSERT_EQ(out, model.front()) << "operation " << i;
        model.pop_front();
      } else {
        ASSERT_EQ(out, 0xDEADBEEF) << "pop on empty must leave the output alone";
      }
    }
    ASSERT_EQ(ring.size(), model.size());
    ASSERT_EQ(ring.empty(), model.empty());
    ASSERT_EQ(ring.free_space(), Capacity - model.size());
  }
}

TEST(SpscRing, BehavesAsABoundedFifoForEveryCapacityAndLoad) {
  uint32_t seed = 3;
  for (int push_percent : {20, 50, 80}) {
    check_random_operations<2>(seed++, 5000, push_percent);
    check_random_operations<16>(seed++, 5000, push_percent);
    check_random_operations<32>(seed++, 5000, push_percent);
    check_random_operations<128>(seed++, 5000, push_percent);
  }
}

TEST(SpscRing, HoldsExactlyItsCapacityAcrossIndexWraps) {
  SpscRing<uint8_t, 128> ring;
  for (int round = 0; round < 10; ++round) {
    for (int i = 0; i < 128; ++i) {
      ASSERT_TRUE(ring.push(static_cast<uint8_t>(i + round)));
    }
    EXPECT_FALSE(ring.push(0)) << "a full ring refuses";
    EXPECT_EQ(ring.size(), 128);
    for (int i = 0; i < 128; ++i) {
      uint8_t out = 0;
      ASSERT_TRUE(ring.pop(&out));
      ASSERT_EQ(out, static_cast<uint8_t>(i + round));
    }
    uint8_t out = 0;
    EXPECT_FALSE(ring.pop(&out)) << "an empty ring refuses";
  }
}

TEST(SpscRing, ClearDropsEverythingHeld) {
  SpscRing<uint16_t, 4> ring;
  ASSERT_TRUE(ring.push(1));
  ASSERT_TRUE(ring.push(2));
  ring.clear();
  EXPECT_TRUE(ring.empty());
  ASSERT_TRUE(ring.push(3));
  uint16_t out = 0;
  ASSERT_TRUE(ring.pop(&out));
  EXPECT_EQ(out, 3);
}

}  // namespace
}  // namespace fw
}  // namespace driftlab
