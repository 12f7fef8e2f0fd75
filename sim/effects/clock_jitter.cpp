// E13 clock_jitter (clock_jitter.hpp).
#include "sim/effects/clock_jitter.hpp"

namespace driftlab::sim {

void ClockJitter::reset(std::uint64_t seed) {
    rng_.clear();
    for (std::size_t c = 0; c <= kChannelCount; ++c) rng_.emplace_back(seed, effect_stream_id(kName, c));
}

double ClockJitter::actual_instant_s(double nominal_s, const EffectContext& ctx) {
    double t = nominal_s * (1.0 + p_.drift_ppm * 1e-6);
    if (p_.jitter_s > 0.0) {
        const std::size_t stream = ctx.channel ? channel_index(*ctx.channel) : kChannelCount;
        t += p_.jitter_s * rng_[stream].normal();
    }
    return t;
}

}  // namespace driftlab::sim
