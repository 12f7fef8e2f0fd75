#include "host/nav/effect_noise.hpp"

#include <numbers>

#include "sim/effects/flicker.hpp"
#include "sim/effects/gauss_markov.hpp"
#include "sim/effects/rate_random_walk.hpp"
#include "sim/motion/trajectory.hpp"

namespace driftlab::host::nav {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

// Each axis's value of a per-effect parameter given for the gyro [deg/s...] and the accelerometers [g...], in SI.
std::array<double, kNavAxes> si(double gyro_dps, const std::array<double, 3>& accel_g) {
    return {gyro_dps * kRadPerDeg, accel_g[0] * sim::kStandardGravity, accel_g[1] * sim::kStandardGravity};
}

}  // namespace

EffectNoise effect_noise(const sim::SimModel& unit) {
    EffectNoise out;
    for (const sim::EffectSpec& e : unit.effects) {
        std::array<double, kNavAxes> add{};
        if (e.name == sim::GaussMarkov::kName) {
            const auto p = sim::params_from_toml<sim::GaussMarkovParams>(e.table, "effects.gauss_markov");
            const auto sigma = si(p.sigma_dps, p.sigma_g);
            for (std::size_t k = 0; k < kNavAxes; ++k)
                add[k] = 2.0 * sigma[k] * sigma[k] / p.tau_s[channel_index(kNavChannels[k])];
        } else if (e.name == sim::RateRandomWalk::kName) {
            const auto p = sim::params_from_toml<sim::RateRandomWalkParams>(e.table, "effects.rate_random_walk");
            const auto k_si = si(p.k_dps_per_sqrt_s, p.k_g_per_sqrt_s);
            for (std::size_t k = 0; k < kNavAxes; ++k) add[k] = k_si[k] * k_si[k];
        } else if (e.name == sim::Flicker::kName) {
            const auto p = sim::params_from_toml<sim::FlickerParams>(e.table, "effects.flicker");
            const auto b = si(p.b_dps, p.b_g);
            const double tau_end = 1.0 / (2.0 * std::numbers::pi * p.f_low_hz);
            for (std::size_t k = 0; k < kNavAxes; ++k) add[k] = flicker_walk_psd(b[k], tau_end);
        } else {
            continue;
        }
        for (std::size_t k = 0; k < kNavAxes; ++k) out.bias_walk_psd[k] += add[k];
        out.used += (out.used.empty() ? "" : ", ") + e.name;
    }
    return out;
}

}  // namespace driftlab::host::nav
