// E8 supply_coupling (supply_coupling.hpp).
#include "sim/effects/supply_coupling.hpp"

#include <numbers>

namespace driftlab::sim {

double SupplyCoupling::supply_deviation_v(const EffectContext& ctx) const {
    double dv = std::isnan(ctx.supply_v) ? 0.0 : ctx.supply_v - p_.nominal_supply_v;
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
