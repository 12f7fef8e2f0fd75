// E10 g_sensitivity: gyro sensitivity to linear acceleration, physical stage; docs/effects.md.
//
// Equation: w_m = w_m + sum_j G_j a_j + sum_j G2_j a_j^2, a = ctx.true_physical accel (x, y, z) [g]
// (IEEE 1431 acceleration-sensitive drift of Coriolis vibratory gyros; MATLAB AccelerationBias; imusim 0.2 deg/s/g
// for the ADXRS300; Groves G_g). The quadratic G2 term rectifies vibration into a DC gyro bias.
// At rest a_z = 1 g gives the constant G_z (absorbed in C2 of the paper's model).
// Cannot represent: frequency-dependent g-sensitivity, g x g cross products, anything from unsimulated axes.
#pragma once

#include "sim/effects/params.hpp"

namespace driftlab::sim {

struct GSensitivityParams {
    std::array<double, 3> g_dps_per_g{};    ///< G_x, G_y, G_z [deg/s/g]
    std::array<double, 3> g2_dps_per_g2{};  ///< G2_x, G2_y, G2_z (rectification) [deg/s/g^2]

    template <class V>
    void visit(V& v) {
        v.field("g_dps_per_g", g_dps_per_g, "deg/s/g", "gyro bias per g along accel x, y, z");
        v.field("g2_dps_per_g2", g2_dps_per_g2, "deg/s/g^2", "gyro bias per g^2 along x, y, z (rectification)");
    }
};

class GSensitivity : public EffectWith<GSensitivity, GSensitivityParams> {
public:
    using Params = GSensitivityParams;
    static constexpr std::string_view kName = "g_sensitivity";
    static constexpr Stage kStage = Stage::physical;
    static constexpr std::string_view kEquation = "w_m += G . a + G2 . a^2";
    static constexpr std::string_view kSummary = "gyro g-sensitivity and vibration rectification (E10)";

    explicit GSensitivity(const Params& params) : EffectWith(params) {}
    void reset(std::uint64_t) override {}
    void apply(ChannelValues& values, const EffectContext& ctx) override;
};

}  // namespace driftlab::sim
