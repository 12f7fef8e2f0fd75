// E12 mains_alias: mains pickup (50/60 Hz and harmonics) at the ADC input, aliased by the sampling instants,
// analog stage; docs/effects.md.
//
// Equation: v_c += A_c [ sin(2 pi f (t + d_c) + phi) + sum_{h>=2} r_h sin(2 pi h f (t + d_c) + h phi) ]
// evaluated at the actual conversion instant t, with an extra multiplexer skew d_c per channel (gap-method.md E12).
// Sampled at f_s the line appears at f_a = abs(f - f_s round(f / f_s)); harmonics alias the same way. Because it
// is a function of the actual instant, per-conversion timing and clock_jitter move the phase as in hardware.
// Cannot represent: mains frequency wander (the grid's +-0.05 Hz), amplitude modulation, pickup after the S/H.
#pragma once

#include <vector>

#include "sim/effects/params.hpp"

namespace driftlab::sim {

struct MainsAliasParams {
    ChannelValues amplitude_v{};         ///< fundamental amplitude per channel at the ADC pin [V]
    double frequency_hz = 50.0;          ///< mains frequency [Hz]
    double phase_rad = 0.0;              ///< fundamental phase at t = 0 [rad]
    std::vector<double> harmonic_ratio;  ///< amplitude of harmonics 2, 3, ... relative to the fundamental [-]
    ChannelValues mux_skew_s{};          ///< extra sampling delay per channel [s]

    template <class V>
    void visit(V& v) {
        v.field("amplitude_v", amplitude_v, "V", "fundamental amplitude per channel (scalar or 4 values)",
                Check::nonneg);
        v.field("frequency_hz", frequency_hz, "Hz", "mains frequency", Check::positive);
        v.field("phase_rad", phase_rad, "rad", "phase of the fundamental at power-on");
        v.field("harmonic_ratio", harmonic_ratio, "-", "amplitudes of harmonics 2, 3, ... relative to the fundamental");
        v.field("mux_skew_s", mux_skew_s, "s", "extra multiplexer sampling delay per channel", Check::nonneg);
    }
};

class MainsAlias : public EffectWith<MainsAlias, MainsAliasParams> {
public:
    using Params = MainsAliasParams;
    static constexpr std::string_view kName = "mains_alias";
    static constexpr Stage kStage = Stage::analog;
    static constexpr std::string_view kEquation = "v += A sum_h r_h sin(2 pi h f (t + d) + h phi), r_1 = 1";
    static constexpr std::string_view kSummary = "mains pickup and harmonics, aliased by the sampling (E12)";

    explicit MainsAlias(const Params& params) : EffectWith(params) {}
    void reset(std::uint64_t) override {}
    void apply(ChannelValues& values, const EffectContext& ctx) override;

    /// Frequency at which a line at `f_hz` appears when sampled at `fs_hz` [Hz].
    static double alias_frequency_hz(double f_hz, double fs_hz);
};

}  // namespace driftlab::sim
