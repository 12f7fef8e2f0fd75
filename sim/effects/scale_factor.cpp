// scale_factor (scale_factor.hpp).
#include "sim/effects/scale_factor.hpp"

namespace driftlab::sim {

void ScaleFactor::apply(ChannelValues& values, const EffectContext& ctx) {
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = first; c < last; ++c) values[c] += p_.error_pct[c] / 100.0 * ctx.true_physical[c];
}

}  // namespace driftlab::sim
