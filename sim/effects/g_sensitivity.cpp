// E10 g_sensitivity (g_sensitivity.hpp).
#include "sim/effects/g_sensitivity.hpp"

namespace driftlab::sim {

void GSensitivity::apply(ChannelValues& values, const EffectContext& ctx) {
    const std::size_t gyro = channel_index(Channel::gyro);
    if (channels_of(ctx).first != gyro) return;
    const std::size_t ax = channel_index(Channel::accel_x);
    for (std::size_t j = 0; j < 3; ++j) {
        const double a_g = ctx.true_physical[ax + j];
        values[gyro] += p_.g_dps_per_g[j] * a_g + p_.g2_dps_per_g2[j] * a_g * a_g;
    }
}

}  // namespace driftlab::sim
