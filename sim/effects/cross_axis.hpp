// E9 cross_axis: accelerometer cross-axis coupling / misalignment matrix, physical stage; docs/effects.md.
//
// Equation: a_m = a_m + (S / 100) a, with a = ctx.true_physical accel (x, y, z) [g] and S a 3x3 matrix in [%]
// (row = measured axis, column = true axis): the off-diagonal terms are cross-axis sensitivity / misalignment
// (MATLAB AxesMisalignment, imusim transform, Groves M_a); a diagonal term is a constant scale-factor error.
// The three ADXL05 are single-axis parts mounted by hand, so 1-3 % is plausible (gap-method.md E9).
// Cannot represent: gyro cross-axis (the unit has one gyro axis and no other rate is simulated), lever arms,
// coupling that changes with temperature. Not identifiable from one static log (absorbed in the bias).
#pragma once

#include "sim/effects/params.hpp"

namespace driftlab::sim {

struct CrossAxisParams {
    std::array<std::array<double, 3>, 3> matrix_pct{};  ///< S: row = measured x, y, z; column = true x, y, z [%]

    template <class V>
    void visit(V& v) {
        v.field("matrix_pct", matrix_pct, "%", "3x3 coupling S, rows measured x,y,z, columns true x,y,z");
    }
};

class CrossAxis : public EffectWith<CrossAxis, CrossAxisParams> {
public:
    using Params = CrossAxisParams;
    static constexpr std::string_view kName = "cross_axis";
    static constexpr Stage kStage = Stage::physical;
    static constexpr std::string_view kEquation = "a_m += (S/100) a";
    static constexpr std::string_view kSummary = "accelerometer cross-axis coupling matrix (E9)";

    explicit CrossAxis(const Params& params) : EffectWith(params) {}
    void reset(std::uint64_t) override {}
    void apply(ChannelValues& values, const EffectContext& ctx) override;
};

}  // namespace driftlab::sim
