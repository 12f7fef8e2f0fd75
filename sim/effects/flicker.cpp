// E3 flicker (flicker.hpp).
#include "sim/effects/flicker.hpp"

#include <numbers>

namespace driftlab::sim {

Flicker::Flicker(const Params& params) : EffectWith(params) {
    if (p_.f_low_hz > 0.0 && p_.f_high_hz > p_.f_low_hz) {  // else no band: identity
        const int n = static_cast<int>(std::ceil(2.0 * std::log10(p_.f_high_hz / p_.f_low_hz) - 1e-9));
        for (int i = -1; i <= n + 1; ++i) {
            tau_s_.push_back(1.0 / (2.0 * std::numbers::pi * p_.f_low_hz * std::pow(10.0, 0.5 * i)));
        }
    }
    reset(0);
}

double Flicker::component_sigma_per_b() { return std::sqrt(std::log(std::sqrt(10.0)) / std::numbers::pi); }

void Flicker::reset(std::uint64_t seed) {
    const ChannelValues b = physical_per_channel(p_.b_dps, p_.b_g);
    const std::size_t n = tau_s_.size();
    rng_.clear();
    state_.assign(kChannelCount * n, 0.0);
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        rng_.emplace_back(seed, effect_stream_id(kName, c));
        if (b[c] <= 0.0) continue;
        for (std::size_t i = 0; i < n; ++i) state_[c * n + i] = b[c] * component_sigma_per_b() * rng_[c].normal();
    }
}

void Flicker::apply(ChannelValues& values, const EffectContext& ctx) {
    const ChannelValues b = physical_per_channel(p_.b_dps, p_.b_g);
    const std::size_t n = tau_s_.size();
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = first; c < last; ++c) {
        if (b[c] <= 0.0) continue;
        const double sigma = b[c] * component_sigma_per_b();
        if (ctx.dt_s != cached_dt_s_) {
            cached_dt_s_ = ctx.dt_s;
            phi_.resize(n);
            innovation_.resize(n);
            for (std::size_t i = 0; i < n; ++i) {
                phi_[i] = std::exp(-ctx.dt_s / tau_s_[i]);
                innovation_[i] = std::sqrt(1.0 - phi_[i] * phi_[i]);
            }
        }
        double sum = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            double& x = state_[c * n + i];
            x = phi_[i] * x + sigma * innovation_[i] * rng_[c].normal();
            sum += x;
        }
        values[c] += sum;
    }
}

}  // namespace driftlab::sim
