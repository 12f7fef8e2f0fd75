// temp_scale_factor (temp_scale_factor.hpp).
#include "sim/effects/temp_scale_factor.hpp"

namespace driftlab::sim {

void TempScaleFactor::apply(ChannelValues& values, const EffectContext& ctx) {
    if (std::isnan(ctx.temperature_degc)) return;
    const double dt_k = ctx.temperature_degc - p_.reference_degc;
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = first; c < last; ++c) values[c] += p_.scale_pct_per_k[c] / 100.0 * dt_k * ctx.true_physical[c];
}

}  // namespace driftlab::sim
