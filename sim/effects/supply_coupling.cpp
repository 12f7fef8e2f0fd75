// E8 supply_coupling (supply_coupling.hpp).
#include "sim/effects/supply_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace driftlab::sim {

namespace {
constexpr double kWanderNodesPerTau = 50.0;
}  // namespace

void SupplyCoupling::reset(std::uint64_t seed) {
    rng_ = Rng(seed, effect_stream_id(kName, 0));
    wander_nodes_.clear();
}

double SupplyCoupling::wander_v(double t_s) const {
    if (p_.wander_v <= 0.0) return 0.0;
    const double h = p_.wander_tau_s / kWanderNodesPerTau;
    const double x = std::max(0.0, t_s) / h;
    const auto node = static_cast<std::size_t>(x);
    const double phi = std::exp(-1.0 / kWanderNodesPerTau);
    // Stationary from power-on, as gauss_markov's bias is.
    if (wander_nodes_.empty()) wander_nodes_.push_back(p_.wander_v * rng_.normal());
    while (wander_nodes_.size() < node + 2)
        wander_nodes_.push_back(phi * wander_nodes_.back() + p_.wander_v * std::sqrt(1.0 - phi * phi) * rng_.normal());
    const double f = x - static_cast<double>(node);
    return (1.0 - f) * wander_nodes_[node] + f * wander_nodes_[node + 1];
}

double SupplyCoupling::supply_deviation_v(const EffectContext& ctx) const {
    double dv = std::isnan(ctx.supply_v) ? 0.0 : ctx.supply_v - p_.nominal_supply_v;
    dv += wander_v(ctx.t_s);
    dv += p_.drift_v * -std::expm1(-ctx.t_s / p_.drift_tau_s);
    dv += p_.ripple_v * std::sin(2.0 * std::numbers::pi * p_.ripple_hz * ctx.t_s + p_.ripple_phase_rad);
    return dv;
}

void SupplyCoupling::apply(ChannelValues& values, const EffectContext& ctx) {
    const double dv = supply_deviation_v(ctx);
    if (dv == 0.0) return;
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = first; c < last; ++c) {
        values[c] = values[c] * (1.0 + (p_.sensor_ratiometric[c] - p_.adc_ratiometric) * dv / p_.nominal_supply_v) +
                    p_.pickup_v_per_v[c] * dv;
    }
}

}  // namespace driftlab::sim
