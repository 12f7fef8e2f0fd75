// bandwidth (bandwidth.hpp).
#include "sim/effects/bandwidth.hpp"

#include <cmath>
#include <numbers>

namespace driftlab::sim {

void Bandwidth::apply(ChannelValues& values, const EffectContext& ctx) {
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = first; c < last; ++c) {
        if (p_.cutoff_hz[c] <= 0.0) continue;
        if (!started_[c]) {
            state_[c] = values[c];
            started_[c] = true;
            continue;
        }
        state_[c] += -std::expm1(-2.0 * std::numbers::pi * p_.cutoff_hz[c] * ctx.dt_s) * (values[c] - state_[c]);
        values[c] = state_[c];
    }
}

}  // namespace driftlab::sim
