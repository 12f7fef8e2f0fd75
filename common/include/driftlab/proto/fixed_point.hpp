// Q8 fixed point: values in ADC counts with 8 fractional bits (1/256 count), as SAMPLE.value_q8 carries them.
// Spec: docs/protocol.md §3.6. Integer only: the firmware has no float, and a 10-bit code times 256 times a
// window of 64 still fits in int32_t (1023 * 256 * 64 < 2^24).
#pragma once

#include <stdint.h>

namespace driftlab {
namespace proto {

constexpr uint8_t kQ8FractionBits = 8;
constexpr int32_t kQ8One = 256;

/// Whole counts to Q8 [counts] -> [counts Q8]. Exact for |counts| < 2^23.
constexpr int32_t counts_to_q8(int32_t counts) { return counts * kQ8One; }

/// num / den in Q8, rounded to nearest with halves away from zero. den > 0. Used for means and least-squares
/// estimates whose numerator is in counts (num * 256 must fit in int32_t, i.e. |num| < 2^23).
constexpr int32_t div_to_q8(int32_t num, int32_t den) {
  return num >= 0 ? (num * kQ8One + den / 2) / den : -((-num * kQ8One + den / 2) / den);
}

/// Q8 to whole counts, rounded to nearest with halves away from zero.
constexpr int32_t q8_round_to_counts(int32_t q8) {
  return q8 >= 0 ? (q8 + kQ8One / 2) / kQ8One : -((-q8 + kQ8One / 2) / kQ8One);
}

}  // namespace proto
}  // namespace driftlab
