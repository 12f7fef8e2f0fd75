// E12 mains_alias (mains_alias.hpp).
#include "sim/effects/mains_alias.hpp"

#include <numbers>

namespace driftlab::sim {

double MainsAlias::alias_frequency_hz(double f_hz, double fs_hz) {
    return std::abs(f_hz - fs_hz * std::round(f_hz / fs_hz));
}

void MainsAlias::apply(ChannelValues& values, const EffectContext& ctx) {
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = first; c < last; ++c) {
        if (p_.amplitude_v[c] == 0.0) continue;
        const double wt = 2.0 * std::numbers::pi * p_.frequency_hz * (ctx.t_s + p_.mux_skew_s[c]) + p_.phase_rad;
        double sum = std::sin(wt);
        for (std::size_t i = 0; i < p_.harmonic_ratio.size(); ++i) {
            sum += p_.harmonic_ratio[i] * std::sin(static_cast<double>(i + 2) * wt);
        }
        values[c] += p_.amplitude_v[c] * sum;
    }
}

}  // namespace driftlab::sim
