// scale_factor: a constant scale-factor error on the true input, physical stage; docs/effects.md.
//
// Equation: y = y + (s/100) u, s in [%], u = ctx.true_physical (IEEE 952/1431 scale-factor error; MATLAB imuSensor
// has it through its sensitivity). At rest only the accelerometer that carries gravity shows it, as a constant the
// base's C2 absorbs; in motion it scales the rate and the specific force. Additive on the true input, so its place
// among the physical effects does not matter.
// Cannot represent: scale-factor nonlinearity or asymmetry (a different error for each sense of rotation).
#pragma once

#include "sim/effects/params.hpp"

namespace driftlab::sim {

struct ScaleFactorParams {
    ChannelValues error_pct{};  ///< scale-factor error per channel [%]

    template <class V>
    void visit(V& v) {
        v.field("error_pct", error_pct, "%", "scale-factor error per channel (scalar or 4 values)");
    }
};

class ScaleFactor : public EffectWith<ScaleFactor, ScaleFactorParams> {
public:
    using Params = ScaleFactorParams;
    static constexpr std::string_view kName = "scale_factor";
    static constexpr Stage kStage = Stage::physical;
    static constexpr std::string_view kEquation = "y += (s/100) u";
    static constexpr std::string_view kSummary = "constant scale-factor error on the true input";

    explicit ScaleFactor(const Params& params) : EffectWith(params) {}
    void reset(std::uint64_t) override {}
    void apply(ChannelValues& values, const EffectContext& ctx) override;
};

}  // namespace driftlab::sim
