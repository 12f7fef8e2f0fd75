// Q8 to counts where a value is read on the host: the one place a Q8 value (SAMPLE.value_q8, the smoother's
// estimate) becomes a fractional count. Beside fixed_point.hpp, which the firmware uses; this header is for the
// host and the simulator only, since the firmware has no floating point. Spec: docs/protocol.md §3.6.
#pragma once

#include <stdint.h>

#include "driftlab/proto/fixed_point.hpp"

namespace driftlab {
namespace proto {

/// Q8 to counts [counts Q8] -> [counts], exact (a power-of-two division of a 32-bit integer).
constexpr double q8_to_counts(int32_t q8) { return static_cast<double>(q8) / kQ8One; }

}  // namespace proto
}  // namespace driftlab
