// E5 gauss_markov (gauss_markov.hpp).
#include "sim/effects/gauss_markov.hpp"

namespace driftlab::sim {

void GaussMarkov::reset(std::uint64_t seed) {
    const ChannelValues sigma = physical_per_channel(p_.sigma_dps, p_.sigma_g);
    rng_.clear();
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        rng_.emplace_back(seed, effect_stream_id(kName, c));
        bias_[c] = sigma[c] > 0.0 ? sigma[c] * rng_[c].normal() : 0.0;
    }
}

void GaussMarkov::apply(ChannelValues& values, const EffectContext& ctx) {
    const ChannelValues sigma = physical_per_channel(p_.sigma_dps, p_.sigma_g);
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = first; c < last; ++c) {
        if (sigma[c] <= 0.0) continue;
        const double phi = std::exp(-ctx.dt_s / p_.tau_s[c]);
        bias_[c] = phi * bias_[c] + sigma[c] * std::sqrt(1.0 - phi * phi) * rng_[c].normal();
        values[c] += bias_[c];
    }
}

}  // namespace driftlab::sim
