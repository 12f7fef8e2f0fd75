// Ideal converter; see adc.hpp.
#include "sim/model/adc.hpp"

#include <cmath>

namespace driftlab::sim {

Adc::Adc(const AdcParams& params)
    : params_(params),
      lsb_v_(params.vref_v / std::ldexp(1.0, params.bits)),
      max_code_(static_cast<std::uint16_t>((1u << params.bits) - 1u)) {}

std::uint16_t Adc::convert_counts(double input_counts) const {
    const double code = std::floor(input_counts + 0.5);
    // NaN (a broken effect) reads as the bottom rail rather than as undefined behaviour in the cast.
    if (!(code > 0.0)) return 0;
    if (code >= static_cast<double>(max_code_)) return max_code_;
    return static_cast<std::uint16_t>(code);
}

}  // namespace driftlab::sim
