// E8 supply_coupling: supply-voltage deviation seen through ratiometric mismatch and direct pickup, with regulator
// warm-up drift and ripple, analog stage; docs/effects.md.
//
// Equation: dV(t) = (V_s(t) - V_nom if the chain models the supply) + D (1 - exp(-t / tau_D))
//                   + A_r sin(2 pi f_r t + phi_r) + w(t)
//           w: a first-order Gauss-Markov wander of the regulator (std sigma_w, correlation time tau_w): a function of
//              t alone, the exact process on a grid of tau_w / 50 from power-on, linear between its nodes (variance
//              at most 1 % low mid-node), so every channel sees one path whatever order the chain converts them in
//              (the gap's replicates convert one channel's whole log after another's)
//           v_c = v_c (1 + (r_c - r_adc) dV / V_nom) + p_c dV
// r_c = 1 for a ratiometric sensor (output scales with the supply, like the ADXL05), 0 for one with its own
// reference; r_adc = 1 when the ADC reference is the supply (AVcc), 0 for a separate reference. The mismatch gives
// the rank-1 common-mode signature with loading proportional to each channel's DC output (gap-method.md E8).
// Cannot represent: radio-TX supply dips synchronous with packets, load steps, supply noise other than one tone and
// one Gauss-Markov wander.
#pragma once

#include <vector>

#include "sim/effects/params.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::sim {

struct SupplyCouplingParams {
    double nominal_supply_v = 5.0;                         ///< V_nom [V]
    ChannelValues sensor_ratiometric{1.0, 1.0, 1.0, 1.0};  ///< r_c, 1 = output scales with supply [-]
    double adc_ratiometric = 1.0;                          ///< r_adc, 1 = ADC reference is the supply [-]
    ChannelValues pickup_v_per_v{};                        ///< p_c, direct additive coupling [V/V]
    double drift_v = 0.0;                                  ///< regulator warm-up drift D [V]
    double drift_tau_s = 600.0;                            ///< regulator warm-up time constant [s]
    double ripple_v = 0.0;                                 ///< ripple amplitude A_r [V]
    double ripple_hz = 100.0;                              ///< ripple frequency f_r [Hz]
    double ripple_phase_rad = 0.0;                         ///< ripple phase at t = 0 [rad]
    double wander_v = 0.0;                                 ///< Gauss-Markov wander's std sigma_w [V]
    double wander_tau_s = 300.0;                           ///< its correlation time tau_w [s]

    template <class V>
    void visit(V& v) {
        v.field("nominal_supply_v", nominal_supply_v, "V", "nominal supply V_nom", Check::positive);
        v.field("sensor_ratiometric", sensor_ratiometric, "-", "r_c per channel: 1 ratiometric, 0 own reference",
                Check::unit_interval);
        v.field("adc_ratiometric", adc_ratiometric, "-", "r_adc: 1 if the ADC reference is the supply",
                Check::unit_interval);
        v.field("pickup_v_per_v", pickup_v_per_v, "V/V", "direct supply pickup per channel");
        v.field("drift_v", drift_v, "V", "regulator warm-up drift D (signed)");
        v.field("drift_tau_s", drift_tau_s, "s", "regulator warm-up time constant", Check::positive);
        v.field("ripple_v", ripple_v, "V", "ripple amplitude", Check::nonneg);
        v.field("ripple_hz", ripple_hz, "Hz", "ripple frequency", Check::positive);
        v.field("ripple_phase_rad", ripple_phase_rad, "rad", "ripple phase at power-on");
        v.field("wander_v", wander_v, "V", "Gauss-Markov supply wander std", Check::nonneg);
        v.field("wander_tau_s", wander_tau_s, "s", "supply wander correlation time", Check::positive);
    }
};

class SupplyCoupling : public EffectWith<SupplyCoupling, SupplyCouplingParams> {
public:
    using Params = SupplyCouplingParams;
    static constexpr std::string_view kName = "supply_coupling";
    static constexpr Stage kStage = Stage::analog;
    static constexpr std::string_view kEquation = "v = v (1 + (r_c - r_adc) dV/V_nom) + p_c dV";
    static constexpr std::string_view kSummary = "supply drift/ripple through ratiometric mismatch and pickup (E8)";

    explicit SupplyCoupling(const Params& params) : EffectWith(params), rng_(0, effect_stream_id(kName, 0)) {
        reset(0);
    }
    void reset(std::uint64_t seed) override;
    void apply(ChannelValues& values, const EffectContext& ctx) override;

    /// Supply deviation dV at an instant [V].
    double supply_deviation_v(const EffectContext& ctx) const;

private:
    /// The wander at `t_s` [V]: its grid drawn as far as t_s needs (once per seed), then interpolated.
    double wander_v(double t_s) const;

    mutable Rng rng_;
    mutable std::vector<double> wander_nodes_;
};

}  // namespace driftlab::sim
