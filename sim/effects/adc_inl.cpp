// E7 adc_inl (adc_inl.hpp).
#include "sim/effects/adc_inl.hpp"

#include <algorithm>

namespace driftlab::sim {

double AdcInl::inl_lsb(double x_counts) const {
    const double u = std::clamp(2.0 * x_counts / 1023.0 - 1.0, -1.0, 1.0);
    const double u2 = u * u;
    return p_.a2_lsb * 0.5 * (3.0 * u2 - 1.0) + p_.a3_lsb * 0.5 * u * (5.0 * u2 - 3.0) +
           p_.a4_lsb * 0.125 * ((35.0 * u2 - 30.0) * u2 + 3.0);
}

void AdcInl::apply(ChannelValues& values, const EffectContext& ctx) {
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = first; c < last; ++c) values[c] += inl_lsb(values[c]);
}

}  // namespace driftlab::sim
