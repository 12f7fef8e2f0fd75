// E1 thermal_second_tc: a second thermal time constant on top of the paper's warm-up (eq. 1), physical stage;
// docs/effects.md.
//
// Equation: y = u + C3 (1 - exp(-t / T2)), t since power-on, added to the base eps(t) = C1 (1 - exp(-t/T)) + C2
// (paper eq. 1), so the bias follows two exponentials: die (T) and package/board (T2) (gap-method.md E1).
// Deterministic: identical on every power-on.
// Cannot represent: a thermal network with more than two nodes (fit as two exponentials), warm-up that depends on
// the ambient temperature or on the previous off-time (a warm restart).
#pragma once

#include "sim/effects/params.hpp"

namespace driftlab::sim {

struct ThermalSecondTcParams {
    double c3_dps = 0.0;                                 ///< gyro amplitude C3 [deg/s]
    std::array<double, 3> c3_g{};                        ///< accel x, y, z amplitude C3 [g]
    ChannelValues t2_s{1800.0, 1800.0, 1800.0, 1800.0};  ///< second time constant T2 per channel [s]

    template <class V>
    void visit(V& v) {
        v.field("c3_dps", c3_dps, "deg/s", "gyro amplitude C3 (signed)");
        v.field("c3_g", c3_g, "g", "accel x, y, z amplitude C3 (signed)");
        v.field("t2_s", t2_s, "s", "second time constant T2 per channel (scalar or 4 values)", Check::positive);
    }
};

class ThermalSecondTc : public EffectWith<ThermalSecondTc, ThermalSecondTcParams> {
public:
    using Params = ThermalSecondTcParams;
    static constexpr std::string_view kName = "thermal_second_tc";
    static constexpr Stage kStage = Stage::physical;
    static constexpr std::string_view kEquation = "y = u + C3 (1 - exp(-t/T2))";
    static constexpr std::string_view kSummary = "second thermal time constant of the warm-up (E1)";

    explicit ThermalSecondTc(const Params& params) : EffectWith(params) {}
    void reset(std::uint64_t) override {}
    void apply(ChannelValues& values, const EffectContext& ctx) override;
};

}  // namespace driftlab::sim
