// E2 ambient_cycle (ambient_cycle.hpp).
#include "sim/effects/ambient_cycle.hpp"

#include <numbers>

namespace driftlab::sim {

double AmbientCycle::lagged_temperature_k(double t_s) const {
    const double half_a = 0.5 * p_.amplitude_k_pp;
    const double w = 2.0 * std::numbers::pi / p_.period_s;
    if (sine_) {
        const double wt = w * p_.lag_s;
        return half_a / std::sqrt(1.0 + wt * wt) * std::sin(w * t_s + p_.phase_rad - std::atan(wt));
    }
    // Square wave: +A/2 for the first half of each cycle (phase measured like the sine's).
    const double cycles = t_s / p_.period_s + p_.phase_rad / (2.0 * std::numbers::pi);
    const double frac = cycles - std::floor(cycles);
    const bool high = frac < 0.5;
    const double s = (high ? frac : frac - 0.5) * p_.period_s;  // time into the current half [s]
    const double level = high ? half_a : -half_a;
    if (p_.lag_s <= 0.0) return level;
    // Steady state: each half starts at -level * tanh(P / (4 tau)) and relaxes towards level.
    const double start = -level * std::tanh(p_.period_s / (4.0 * p_.lag_s));
    return level + (start - level) * std::exp(-s / p_.lag_s);
}

void AmbientCycle::apply(ChannelValues& values, const EffectContext& ctx) {
    if (p_.amplitude_k_pp == 0.0) return;
    const ChannelValues k = physical_per_channel(p_.coupling_dps_per_k, p_.coupling_g_per_k);
    const double theta = lagged_temperature_k(ctx.t_s);
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = first; c < last; ++c) values[c] += k[c] * theta;
}

}  // namespace driftlab::sim
