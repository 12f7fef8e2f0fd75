// LsWindow: O(1) integer update of the least-squares sums, one rounded division per estimate.
// Formulas and bounds: docs/firmware.md "Least squares on the MCU".
#include "firmware/core/ls_window.hpp"

#include "driftlab/proto/fixed_point.hpp"

namespace driftlab {
namespace fw {
namespace {

using proto::div_to_q8;
using proto::kQ8One;

// proto::div_to_q8 needs |numerator| * 256 (+ half the divisor) to fit int32_t.
constexpr int32_t kMaxQ8Numerator = (2147483647 - 4160) / kQ8One;

// Largest |6 S1 - 2 (n - 2) S0| any window can produce: every code at kMaxCode where its weight 6x - 2(n - 2) has
// one sign, 0 elsewhere. The estimate shifts this numerator left by 8 bits, so it must stay below 2^31 / 256.
constexpr int32_t worst_line_numerator(int32_t n) {
  int32_t positive = 0;
  int32_t negative = 0;
  for (int32_t x = 0; x < n; ++x) {
    const int32_t weight = 6 * x - 2 * (n - 2);
    if (weight > 0) {
      positive += weight;
    } else {
      negative -= weight;
    }
  }
  return (positive > negative ? positive : negative) * static_cast<int32_t>(LsWindow::kMaxCode);
}

constexpr int32_t worst_line_numerator_up_to(int32_t n) {
  int32_t worst = 0;
  for (int32_t m = 1; m <= n; ++m) {
    const int32_t v = worst_line_numerator(m);
    worst = v > worst ? v : worst;
  }
  return worst;
}

static_assert(worst_line_numerator_up_to(LsWindow::kMaxWindow) <= kMaxQ8Numerator,
              "order-1 numerator in Q8 must fit int32 for every window up to kMaxWindow");
static_assert(static_cast<int32_t>(LsWindow::kMaxWindow) * LsWindow::kMaxCode <= kMaxQ8Numerator,
              "order-0 sum in Q8 must fit int32");

bool is_saturated(uint16_t code_counts) { return code_counts == 0 || code_counts >= LsWindow::kMaxCode; }

}  // namespace

void LsWindow::reset(uint8_t window) {
  window_ = window == 0 ? 1 : (window > kMaxWindow ? kMaxWindow : window);
  n_ = 0;
  oldest_ = 0;
  s0_ = 0;
  s1_ = 0;
  saturated_count_ = 0;
}

void LsWindow::push(uint16_t code_counts) {
  // The store is a ring of exactly window_ slots: during warm-up oldest_ stays 0 and sample x sits in slot x;
  // once full, the newest overwrites the oldest's slot.
  if (n_ < window_) {
    codes_counts_[n_] = code_counts;
    s1_ += static_cast<uint32_t>(n_) * code_counts;
    s0_ += code_counts;
    ++n_;
  } else {
    // The oldest (x = 0) leaves, the others move to x - 1, the new one takes x = N - 1.
    const uint16_t old_counts = codes_counts_[oldest_];
    s1_ = s1_ - (s0_ - old_counts) + static_cast<uint32_t>(window_ - 1U) * code_counts;
    s0_ = s0_ - old_counts + code_counts;
    if (is_saturated(old_counts)) {
      --saturated_count_;
    }
    codes_counts_[oldest_] = code_counts;
    const uint8_t next_oldest = static_cast<uint8_t>(oldest_ + 1U);
    oldest_ = next_oldest >= window_ ? 0 : next_oldest;
  }
  if (is_saturated(code_counts)) {
    ++saturated_count_;
  }
}

int32_t LsWindow::estimate_q8(FitOrder order) const {
  if (n_ == 0) {
    return 0;
  }
  const int32_t n = n_;
  const int32_t s0 = static_cast<int32_t>(s0_);
  if (order == FitOrder::mean || n_ == 1) {
    return div_to_q8(s0, n);
  }
  const int32_t s1 = static_cast<int32_t>(s1_);
  const int32_t numerator = 6 * s1 - 2 * (n - 2) * s0;
  return div_to_q8(numerator, n * (n + 1));
}

}  // namespace fw
}  // namespace driftlab
