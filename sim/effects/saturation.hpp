// E14 saturation: sensor or amplifier range clipping, physical or analog stage; docs/effects.md.
//
// Equation: y = clip(y, lo, hi), with the rails in physical units (stage = "physical": [deg/s], [g]) for the
// sensor's measurement range, or at the amplifier output (stage = "analog": [V]) for rail clipping. This comes
// before the ADC's own 0..1023 clip, which the chain always applies (gap-method.md E14; MATLAB MeasurementRange,
// NPS/JSBSim min/max). Rails are +-inf by default (off). Asymmetric ranges (Z on 0..2 g) are allowed.
// Cannot represent: soft saturation (compression before the rail), recovery time after overload, latch-up.
#pragma once

#include <limits>
#include <string>

#include "sim/effects/params.hpp"

namespace driftlab::sim {

struct SaturationParams {
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    std::string stage = "physical";                    ///< "physical" (sensor range) or "analog" (amplifier rails)
    double min_dps = -kInf;                            ///< gyro lower range [deg/s]
    double max_dps = kInf;                             ///< gyro upper range [deg/s]
    std::array<double, 3> min_g{-kInf, -kInf, -kInf};  ///< accel x, y, z lower range [g]
    std::array<double, 3> max_g{kInf, kInf, kInf};     ///< accel x, y, z upper range [g]
    ChannelValues min_v{-kInf, -kInf, -kInf, -kInf};   ///< lower amplifier rail per channel [V]
    ChannelValues max_v{kInf, kInf, kInf, kInf};       ///< upper amplifier rail per channel [V]

    template <class V>
    void visit(V& v) {
        v.choice("stage", stage, {"physical", "analog"}, "where the clipping acts");
        v.field("min_dps", min_dps, "deg/s", "gyro lower range (stage physical)", Check::limit);
        v.field("max_dps", max_dps, "deg/s", "gyro upper range (stage physical)", Check::limit);
        v.field("min_g", min_g, "g", "accel x, y, z lower range (stage physical)", Check::limit);
        v.field("max_g", max_g, "g", "accel x, y, z upper range (stage physical)", Check::limit);
        v.field("min_v", min_v, "V", "lower rail per channel (stage analog)", Check::limit);
        v.field("max_v", max_v, "V", "upper rail per channel (stage analog)", Check::limit);
    }
    void validate(const TomlReader& r) const;
};

class Saturation : public EffectWith<Saturation, SaturationParams> {
public:
    using Params = SaturationParams;
    static constexpr std::string_view kName = "saturation";
    static constexpr Stage kStage = Stage::physical;  // default; `stage` chooses
    static constexpr std::string_view kEquation = "y = clip(y, lo, hi)";
    static constexpr std::string_view kSummary = "sensor range or amplifier rail clipping (E14)";

    explicit Saturation(const Params& params) : EffectWith(params), analog_(params.stage == "analog") {}
    Stage stage() const override { return analog_ ? Stage::analog : Stage::physical; }
    void reset(std::uint64_t) override {}
    void apply(ChannelValues& values, const EffectContext& ctx) override;

private:
    bool analog_;
};

}  // namespace driftlab::sim
