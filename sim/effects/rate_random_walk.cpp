// E4 rate_random_walk (rate_random_walk.hpp).
#include "sim/effects/rate_random_walk.hpp"

namespace driftlab::sim {

void RateRandomWalk::reset(std::uint64_t seed) {
    rng_.clear();
    for (std::size_t c = 0; c < kChannelCount; ++c) rng_.emplace_back(seed, effect_stream_id(kName, c));
    bias_.fill(0.0);
}

void RateRandomWalk::apply(ChannelValues& values, const EffectContext& ctx) {
    const ChannelValues k = physical_per_channel(p_.k_dps_per_sqrt_s, p_.k_g_per_sqrt_s);
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = first; c < last; ++c) {
        if (k[c] <= 0.0) continue;
        // The walk runs from power-on: the first instant's step covers the time before it (--warm included).
        bias_[c] += k[c] * std::sqrt(ctx.dt_s + ctx.since_power_on_s) * rng_[c].normal();
        values[c] += bias_[c];
    }
}

}  // namespace driftlab::sim
