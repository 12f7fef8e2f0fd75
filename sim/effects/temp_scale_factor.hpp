// temp_scale_factor: temperature-dependent scale factor acting on the true physical input, physical stage;
// docs/effects.md.
//
// Equation: y = y + s (T - T_ref) u, s in [%/K] / 100, u = ctx.true_physical (MATLAB imuSensor
// TemperatureScaleFactor; IEEE 952/1431 scale-factor error epsilon_k; the Gyrostar family's detection
// sensitivity is temperature dependent, Murata JPH0791959A). Additive on the true input, so its place among the
// physical effects does not matter. T is the chain's temperature (ctx.temperature_degc).
// Cannot represent: anything when the chain does not model temperature (NaN: identity); nonlinear (quadratic)
// temperature dependence; scale-factor asymmetry or nonlinearity in u.
#pragma once

#include "sim/effects/params.hpp"

namespace driftlab::sim {

struct TempScaleFactorParams {
    ChannelValues scale_pct_per_k{};  ///< scale-factor change per kelvin, per channel [%/K]
    double reference_degc = 25.0;     ///< temperature of the nominal scale factor [degC]

    template <class V>
    void visit(V& v) {
        v.field("scale_pct_per_k", scale_pct_per_k, "%/K", "scale-factor tempco per channel (scalar or 4 values)");
        v.field("reference_degc", reference_degc, "degC", "temperature at which the scale factor is nominal");
    }
};

class TempScaleFactor : public EffectWith<TempScaleFactor, TempScaleFactorParams> {
public:
    using Params = TempScaleFactorParams;
    static constexpr std::string_view kName = "temp_scale_factor";
    static constexpr Stage kStage = Stage::physical;
    static constexpr std::string_view kEquation = "y += (s/100) (T - T_ref) u";
    static constexpr std::string_view kSummary = "temperature-dependent scale factor on the true input";

    explicit TempScaleFactor(const Params& params) : EffectWith(params) {}
    void reset(std::uint64_t) override {}
    void apply(ChannelValues& values, const EffectContext& ctx) override;
};

}  // namespace driftlab::sim
