// E11 vibration: table vibration, a real input (tones and band-limited random motion), physical stage;
// docs/effects.md.
//
// Equation: u_c(t) += sum_m A_cm sin(2 pi f_m t + phi_m)                       (tones)
//                   + sum_k r_c sqrt(2/K) sin(2 pi F_ck t + psi_ck)            (band-limited random)
// with F_ck ~ U[f_lo, f_hi] and psi_ck ~ U[0, 2 pi) drawn at reset from the channel's substream (a random-phase
// multisine: Gaussian by the central limit theorem, flat expected PSD in the band, rms exactly r_c).
// A continuous function of t, so it is evaluated at the actual (jittered, per-conversion) instants and aliases
// exactly as sampled motion does: f_a = abs(f - f_s round(f / f_s)) (gap-method.md E11; gnss-ins-sim env,
// ArduPilot SIM_VIB_FREQ). It is an input: the chain adds it to ctx.true_physical too (effect.hpp, "Order"), so
// g_sensitivity and cross_axis see it. Cost: (tones + K) sines per channel per instant. Cannot represent: geometric
// coherence between axes of the random part (each channel has its own lines), bursts (door slams), the sensor's own
// bandwidth (no low-pass before sampling).
#pragma once

#include <vector>

#include "sim/effects/params.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::sim {

struct VibrationParams {
    std::vector<double> tone_hz;           ///< tone frequencies [Hz]
    std::vector<double> tone_dps;          ///< gyro amplitude of each tone, empty = 0 [deg/s]
    std::vector<double> tone_g_x;          ///< accel x amplitude of each tone, empty = 0 [g]
    std::vector<double> tone_g_y;          ///< accel y amplitude of each tone, empty = 0 [g]
    std::vector<double> tone_g_z;          ///< accel z amplitude of each tone, empty = 0 [g]
    std::vector<double> tone_phase_rad;    ///< phase of each tone at t = 0, empty = 0 [rad]
    double random_rms_dps = 0.0;           ///< gyro rms of the band-limited random part [deg/s]
    std::array<double, 3> random_rms_g{};  ///< accel x, y, z rms of the random part [g]
    double band_low_hz = 5.0;              ///< lower edge of the random band [Hz]
    double band_high_hz = 50.0;            ///< upper edge of the random band [Hz]
    std::uint64_t random_lines = 64;       ///< number of random-phase lines K per channel [-]

    template <class V>
    void visit(V& v) {
        v.field("tone_hz", tone_hz, "Hz", "tone frequencies", Check::positive);
        v.field("tone_dps", tone_dps, "deg/s", "gyro amplitude per tone (same length as tone_hz)");
        v.field("tone_g_x", tone_g_x, "g", "accel x amplitude per tone");
        v.field("tone_g_y", tone_g_y, "g", "accel y amplitude per tone");
        v.field("tone_g_z", tone_g_z, "g", "accel z amplitude per tone");
        v.field("tone_phase_rad", tone_phase_rad, "rad", "phase per tone at power-on");
        v.field("random_rms_dps", random_rms_dps, "deg/s", "gyro rms of band-limited random vibration", Check::nonneg);
        v.field("random_rms_g", random_rms_g, "g", "accel x, y, z rms of band-limited random vibration", Check::nonneg);
        v.field("band_low_hz", band_low_hz, "Hz", "lower edge of the random band", Check::positive);
        v.field("band_high_hz", band_high_hz, "Hz", "upper edge of the random band", Check::positive);
        v.field("random_lines", random_lines, "-", "random-phase lines per channel (>= 1)");
    }
    void validate(const TomlReader& r) const;
};

class Vibration : public EffectWith<Vibration, VibrationParams> {
public:
    using Params = VibrationParams;
    static constexpr std::string_view kName = "vibration";
    static constexpr Stage kStage = Stage::physical;
    static constexpr std::string_view kEquation =
        "u += sum_m A_m sin(2 pi f_m t + phi_m) + sum_k r sqrt(2/K) sin(2 pi F_k t + psi_k)";
    static constexpr std::string_view kSummary = "table vibration: tones and band-limited random motion (E11)";

    explicit Vibration(const Params& params) : EffectWith(params) { reset(0); }
    bool is_input() const override { return true; }
    void reset(std::uint64_t seed) override;
    void apply(ChannelValues& values, const EffectContext& ctx) override;

private:
    double tone_amplitude(std::size_t channel, std::size_t tone) const;
    struct Line {
        double frequency_hz;
        double phase_rad;
    };
    std::vector<Line> lines_;  // channel-major, random_lines per channel
};

}  // namespace driftlab::sim
