// E15 spikes: random impulsive outliers, analog (EMI on the ADC input) or converter (bit errors) stage;
// docs/effects.md.
//
// Equation: at each instant of channel c, with probability p = 1 - exp(-lambda_c dt) (a Poisson process of rate
// lambda_c sampled at the instants; two events inside one interval count once) the value gets an impulse:
//   gaussian:  y += s_c eta          student_t: y += s_c t_nu (heavy tails)
//   bit_flip:  y = round(y) XOR 2^b, b ~ U{0..9} (converter stage only: a flipped bit of the 10-bit word)
// Placed before the firmware's smoother, a spike comes out kernel-shaped (h, M samples); link corruption (after the
// smoother) is the link model's job (gap-method.md E15 vs E16).
// Cannot represent: common-mode bursts hitting all channels at once, spikes lasting longer than one conversion.
#pragma once

#include <string>
#include <vector>

#include "sim/effects/params.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::sim {

struct SpikesParams {
    std::string stage = "converter";        ///< "analog" [V] or "converter" [counts]
    ChannelValues rate_hz{};                ///< spike rate lambda per channel [1/s]
    std::string distribution = "gaussian";  ///< "gaussian", "student_t" or "bit_flip"
    ChannelValues scale_v{};                ///< amplitude scale s per channel, stage analog [V]
    ChannelValues scale_counts{};           ///< amplitude scale s per channel, stage converter [counts]
    std::uint64_t student_dof = 3;          ///< degrees of freedom nu of student_t [-]

    template <class V>
    void visit(V& v) {
        v.choice("stage", stage, {"analog", "converter"}, "where the spikes enter");
        v.field("rate_hz", rate_hz, "1/s", "spike rate per channel (scalar or 4 values)", Check::nonneg);
        v.choice("distribution", distribution, {"gaussian", "student_t", "bit_flip"}, "amplitude distribution");
        v.field("scale_v", scale_v, "V", "amplitude scale per channel (stage analog)", Check::nonneg);
        v.field("scale_counts", scale_counts, "counts", "amplitude scale per channel (stage converter)", Check::nonneg);
        v.field("student_dof", student_dof, "-", "degrees of freedom of student_t (1..100)");
    }
    void validate(const TomlReader& r) const;
};

class Spikes : public EffectWith<Spikes, SpikesParams> {
public:
    using Params = SpikesParams;
    static constexpr std::string_view kName = "spikes";
    static constexpr Stage kStage = Stage::converter;  // default; `stage` chooses
    static constexpr std::string_view kEquation = "P(spike) = 1 - exp(-lambda dt); y += s eta | s t_nu | bit flip";
    static constexpr std::string_view kSummary = "random impulsive outliers, Poisson in time (E15)";

    explicit Spikes(const Params& params);
    Stage stage() const override { return analog_ ? Stage::analog : Stage::converter; }
    void reset(std::uint64_t seed) override;
    void apply(ChannelValues& values, const EffectContext& ctx) override;

private:
    enum class Distribution : std::uint8_t { gaussian, student_t, bit_flip };
    double amplitude(std::size_t channel);
    bool analog_;
    Distribution distribution_;
    std::vector<Rng> rng_;
};

}  // namespace driftlab::sim
