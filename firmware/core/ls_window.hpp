// LsWindow: sliding-window least squares of order 0 or 1 over one channel's last N conversions, evaluated at the
// newest conversion. Derivation and overflow bounds: docs/firmware.md "Least squares on the MCU".
//
// With the window's samples at x = 0..n-1 (newest at x = n-1) and the running sums
//   S0 = sum y_x,   S1 = sum x * y_x,
// the fit evaluated at x = n-1 is
//   order 0:  yhat = S0 / n
//   order 1:  yhat = (6 S1 - 2 (n - 2) S0) / (n (n + 1))
// When a sample leaves, every remaining x drops by one, so S1 loses S0 - y_old: both sums update exactly in
// integers in O(1) per conversion; the one division happens per output, not per conversion.
#pragma once

#include <stdint.h>

namespace driftlab {
namespace fw {

/// Polynomial order of the fit; the numbers are the CONFIG field `fit_order`.
enum class FitOrder : uint8_t { mean = 0, line = 1 };

class LsWindow {
 public:
  /// Largest window N [conversions]; sizes the sample store (64 x 2 bytes per channel).
  static constexpr uint8_t kMaxWindow = 64;
  /// Largest code of the 10-bit converter [counts]; 0 and this value mark a saturated conversion.
  static constexpr uint16_t kMaxCode = 1023;

  LsWindow() { reset(1); }

  /// Empties the window and sets N (1..kMaxWindow, the caller validated it; out-of-range values are clamped).
  void reset(uint8_t window);

  /// Adds the newest conversion `code_counts` (0..kMaxCode), dropping the oldest once N are held. O(1).
  void push(uint16_t code_counts);

  /// Least-squares value at the newest conversion [counts, Q8 = 1/256 count], rounded to nearest with ties away
  /// from zero. Uses the n() samples held (fewer than N during warm-up); 0 when the window is empty.
  int32_t estimate_q8(FitOrder order) const;

  uint8_t window() const { return window_; }
  /// Conversions currently in the window (< window() during warm-up).
  uint8_t n() const { return n_; }
  /// True when a code 0 or kMaxCode is inside the window.
  bool saturated() const { return saturated_count_ != 0; }

 private:
  uint16_t codes_counts_[kMaxWindow];  // ring of window_ slots holding the last n_ codes; oldest at oldest_
  uint32_t s0_;                        // sum of codes, <= 64 * 1023
  uint32_t s1_;                        // sum of x * code with x = 0 (oldest) .. n-1 (newest), <= 2016 * 1023
  uint8_t window_;
  uint8_t n_;
  uint8_t oldest_;
  uint8_t saturated_count_;  // codes 0 or kMaxCode inside the window
};

}  // namespace fw
}  // namespace driftlab
