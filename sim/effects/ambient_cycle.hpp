// E2 ambient_cycle: ambient temperature cycling (HVAC) through a first-order thermal lag, physical stage;
// docs/effects.md.
//
// Equation: y = u + k_T * theta(t), theta = H_th * dT_amb, H_th(s) = 1 / (1 + s tau_lag) (gap-method.md E2).
//   dT_amb is a sine or a square (thermostat) wave of peak-to-peak A and period P with phase phi.
//   theta is the periodic steady state (the cycling ran long before power-on), in closed form:
//     sine:   theta = (A/2) / sqrt(1 + (w tau)^2) sin(w t + phi - atan(w tau)),  w = 2 pi / P
//     square: each half-period relaxes exponentially towards +-A/2 from -+(A/2) tanh(P / (4 tau)).
//   Cost: one exp per instant; no state.
// Cannot represent: thermostat hysteresis with a wandering period, a sawtooth/triangle profile, a temperature
// gradient (rate) coupling. The temperature itself is not output; the sensor chain takes kMeanDegc + theta(t) as
// its temperature (ctx.temperature_degc, which temp_scale_factor reads).
#pragma once

#include <string>

#include "sim/effects/params.hpp"

namespace driftlab::sim {

struct AmbientCycleParams {
    std::string waveform = "square";           ///< "sine" or "square" (thermostat)
    double amplitude_k_pp = 0.0;               ///< ambient swing, peak to peak [K]
    double period_s = 1200.0;                  ///< cycle period P [s]
    double phase_rad = 0.0;                    ///< phase of the ambient wave at t = 0 [rad]
    double lag_s = 600.0;                      ///< first-order thermal lag of the unit, 0 = none [s]
    double coupling_dps_per_k = 0.0;           ///< gyro bias per kelvin of lagged temperature [deg/s/K]
    std::array<double, 3> coupling_g_per_k{};  ///< accel x, y, z bias per kelvin [g/K]

    template <class V>
    void visit(V& v) {
        v.choice("waveform", waveform, {"sine", "square"}, "ambient wave shape");
        v.field("amplitude_k_pp", amplitude_k_pp, "K", "ambient swing, peak to peak", Check::nonneg);
        v.field("period_s", period_s, "s", "cycle period P", Check::positive);
        v.field("phase_rad", phase_rad, "rad", "phase of the ambient wave at power-on");
        v.field("lag_s", lag_s, "s", "first-order thermal lag tau (0 = none)", Check::nonneg);
        v.field("coupling_dps_per_k", coupling_dps_per_k, "deg/s/K", "gyro coupling k_T");
        v.field("coupling_g_per_k", coupling_g_per_k, "g/K", "accel x, y, z coupling k_T");
    }
};

class AmbientCycle : public EffectWith<AmbientCycle, AmbientCycleParams> {
public:
    using Params = AmbientCycleParams;
    static constexpr std::string_view kName = "ambient_cycle";
    static constexpr Stage kStage = Stage::physical;
    static constexpr std::string_view kEquation = "y = u + k_T (dT_amb * 1/(1 + s tau_lag))(t)";
    static constexpr std::string_view kSummary = "ambient (HVAC) temperature cycling through a thermal lag (E2)";

    explicit AmbientCycle(const Params& params) : EffectWith(params), sine_(params.waveform == "sine") {}
    void reset(std::uint64_t) override {}
    void apply(ChannelValues& values, const EffectContext& ctx) override;

    /// Lagged temperature deviation theta(t) [K].
    double lagged_temperature_k(double t_s) const;
    /// The unit's temperature, the ambient mean plus theta(t) [degC]: the chain's temperature (temp_scale_factor).
    double temperature_degc(double t_s) const override { return kMeanDegc + lagged_temperature_k(t_s); }
    /// The ambient wave's mean [degC]; the couplings see only the swing, temp_scale_factor the whole temperature.
    static constexpr double kMeanDegc = 25.0;

private:
    bool sine_;
};

}  // namespace driftlab::sim
