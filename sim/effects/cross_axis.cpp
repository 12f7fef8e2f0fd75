// E9 cross_axis (cross_axis.hpp).
#include "sim/effects/cross_axis.hpp"

#include <algorithm>

namespace driftlab::sim {

void CrossAxis::apply(ChannelValues& values, const EffectContext& ctx) {
    const std::size_t ax = channel_index(Channel::accel_x);
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = std::max(first, ax); c < last; ++c) {
        const auto& row = p_.matrix_pct[c - ax];
        for (std::size_t j = 0; j < 3; ++j) values[c] += row[j] / 100.0 * ctx.true_physical[ax + j];
    }
}

}  // namespace driftlab::sim
