// LsWindow against the double-precision least-squares reference (ls_reference.hpp): every window 1..64, both
// orders, warm-up, long sliding runs and the worst-case inputs; saturation bookkeeping against a window scan.
#include "firmware/core/ls_window.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <deque>
#include <functional>
#include <random>

#include "tests/firmware/ls_reference.hpp"

namespace driftlab {
namespace fw {
namespace {

// Half an output LSB: Q8 output, so 1/512 count. Ties round away from zero and land exactly on the bound.
constexpr double kHalfLsbCounts = 1.0 / 512.0;
constexpr double kFpSlackCounts = 1e-9;

FitOrder order_of(int order) { return order == 0 ? FitOrder::mean : FitOrder::line; }

// Pushes `count` codes from `code_at(k)` into a window of `window`, checking estimate, fill level and saturation
// after every push against a reference model of the last `window` codes.
void check_sequence(uint8_t window, int order, int count, const std::function<uint16_t(int)>& code_at) {
  LsWindow lsw;
  lsw.reset(window);
  std::deque<uint16_t> held;
  for (int k = 0; k < count; ++k) {
    const uint16_t code = code_at(k);
    lsw.push(code);
    held.push_back(code);
    if (held.size() > window) {
      held.pop_front();
    }
    const double expected_counts = test::ls_reference(held, order);
    const double got_counts = lsw.estimate_q8(order_of(order)) / 256.0;
    ASSERT_LE(std::fabs(got_counts - expected_counts), kHalfLsbCounts + kFpSlackCounts)
        << "window " << int(window) << " order " << order << " after " << (k + 1) << " pushes";
    ASSERT_EQ(lsw.n(), held.size());
    bool saturated = false;
    for (uint16_t c : held) {
      saturated = saturated || c == 0 || c == 1023;
    }
    ASSERT_EQ(lsw.saturated(), saturated) << "window " << int(window) << " after " << (k + 1) << " pushes";
  }
}

TEST(LsWindow, MatchesDoubleReferenceOnRandomCodesForEveryWindowAndOrder) {
  std::mt19937 rng(20260101);
  std::uniform_int_distribution<int> code(0, 1023);
  for (int order = 0; order <= 1; ++order) {
    for (int window = 1; window <= LsWindow::kMaxWindow; ++window) {
      // Warm-up, then enough pushes for the ring to wrap several times.
      check_sequence(static_cast<uint8_t>(window), order, 5 * window + 20,
                     [&](int) { return static_cast<uint16_t>(code(rng)); });
    }
  }
}

TEST(LsWindow, MatchesDoubleReferenceOnWorstCaseInputs) {
  const std::function<uint16_t(int)> patterns[] = {
      [](int) -> uint16_t { return 0; },
      [](int) -> uint16_t { return 1023; },
      [](int k) -> uint16_t { return k % 2 == 0 ? 0 : 1023; },
      // A step inside the window: the order-1 estimate overshoots beyond 0..1023, the largest numerators.
      [](int k) -> uint16_t { return (k / 64) % 2 == 0 ? 0 : 1023; },
      [](int k) -> uint16_t { return (k / 21) % 3 == 0 ? 0 : 1023; },
  };
  for (const auto& pattern : patterns) {
    for (int order = 0; order <= 1; ++order) {
      for (int window = 1; window <= LsWindow::kMaxWindow; ++window) {
        check_sequence(static_cast<uint8_t>(window), order, 3 * window + 130, pattern);
      }
    }
  }
}

TEST(LsWindow, StaysExactAfterManyWrapsOfTheRing) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> code(0, 1023);
  for (uint8_t window : {uint8_t{1}, uint8_t{2}, uint8_t{37}, uint8_t{63}, uint8_t{64}}) {
    for (int order = 0; order <= 1; ++order) {
      check_sequence(window, order, 100000, [&](int) { return static_cast<uint16_t>(code(rng)); });
    }
  }
}

TEST(LsWindow, Order1ReproducesALineExactlyAndOrder0ItsMean) {
  // Closed forms: a line is its own LS fit; the mean of N equally spaced values lags the newest by (N-1)/2 steps.
  LsWindow lsw;
  lsw.reset(16);
  for (int k = 0; k < 40; ++k) {
    lsw.push(static_cast<uint16_t>(100 + 3 * k));
  }
  EXPECT_EQ(lsw.estimate_q8(FitOrder::line), (100 + 3 * 39) * 256);
  EXPECT_EQ(lsw.estimate_q8(FitOrder::mean), (100 + 3 * 39) * 256 - 3 * 15 * 128);
}

TEST(LsWindow, EmptyWindowEstimatesZeroAndResetForgetsSamples) {
  LsWindow lsw;
  lsw.reset(8);
  EXPECT_EQ(lsw.n(), 0);
  EXPECT_EQ(lsw.estimate_q8(FitOrder::mean), 0);
  lsw.push(1023);
  EXPECT_TRUE(lsw.saturated());
  lsw.reset(4);
  EXPECT_EQ(lsw.window(), 4);
  EXPECT_EQ(lsw.n(), 0);
  EXPECT_FALSE(lsw.saturated());
  lsw.push(10);
  EXPECT_EQ(lsw.estimate_q8(FitOrder::line), 10 * 256);
}

TEST(LsWindow, RoundsToTheNearestQ8StepOnBothSides) {
  // Hand-computed fits; a tie cannot occur (n(n+1) <= 4160 never holds the factor 512 it would need).
  LsWindow lsw;
  lsw.reset(3);
  lsw.push(0);
  lsw.push(1);
  lsw.push(1);
  // Mean 2/3 count = 170.67 Q8.
  EXPECT_EQ(lsw.estimate_q8(FitOrder::mean), 171);
  lsw.reset(8);
  lsw.push(5);
  lsw.push(3);
  lsw.push(0);
  // Line through (0,5), (1,3), (2,0): mean 8/3, slope -5/2, at x = 2: 1/6 count = 42.67 Q8.
  EXPECT_EQ(lsw.estimate_q8(FitOrder::line), 43);
  lsw.reset(3);
  lsw.push(4);
  lsw.push(0);
  lsw.push(0);
  // (0,4), (1,0), (2,0): mean 4/3, slope -2, at x = 2: -2/3 count = -170.67 Q8.
  EXPECT_EQ(lsw.estimate_q8(FitOrder::line), -171);
  // The window slides to {0, 0, 3}: mean 1, slope 3/2, at x = 2: 2.5 counts exactly.
  lsw.push(3);
  EXPECT_EQ(lsw.estimate_q8(FitOrder::line), 640);
}

// The smoother's lag on a changing input (docs/sim.md §Motion): on a ramp of k counts per conversion the mean of the
// last N conversions reads the value of (N - 1) / 2 conversions before the newest, k (N - 1) / 2 counts behind it,
// while the line fit reads the newest value itself. In closed form, so checked exactly (Q8).
TEST(LsWindow, OnARampTheMeanLagsHalfTheWindowAndTheLineDoesNot) {
  for (int window : {1, 2, 8, 25, 64}) {
    for (int slope : {1, 3, -2}) {
      LsWindow lsw;
      lsw.reset(static_cast<uint8_t>(window));
      int newest = 0;
      for (int k = 0; k < 2 * window; ++k) {
        newest = 300 + slope * k;
        lsw.push(static_cast<uint16_t>(newest));
      }
      // 256 x (newest - slope (N - 1) / 2) is a whole number: 128 x slope x (N - 1).
      EXPECT_EQ(lsw.estimate_q8(FitOrder::mean), 256 * newest - 128 * slope * (window - 1)) << window << " " << slope;
      EXPECT_EQ(lsw.estimate_q8(FitOrder::line), 256 * newest) << window << " " << slope;
    }
  }
}

}  // namespace
}  // namespace fw
}  // namespace driftlab
