// E1 thermal_second_tc (thermal_second_tc.hpp).
#include "sim/effects/thermal_second_tc.hpp"

namespace driftlab::sim {

void ThermalSecondTc::apply(ChannelValues& values, const EffectContext& ctx) {
    const ChannelValues c3 = physical_per_channel(p_.c3_dps, p_.c3_g);
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = first; c < last; ++c) values[c] += c3[c] * -std::expm1(-ctx.t_s / p_.t2_s[c]);
}

}  // namespace driftlab::sim
