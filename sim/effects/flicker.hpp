// E3 flicker: bias instability (1/f noise) as a sum of first-order Gauss-Markov processes, physical stage;
// docs/effects.md.
//
// Target (IEEE 952 bias instability B): two-sided PSD B^2 / (2 pi f) between f_low and f_high, so the Allan
// deviation is flat at sqrt(2 ln 2 / pi) B = 0.664 B.
// Realisation: Gauss-Markov components with corner frequencies f_i = f_low 10^(i/2), i = -1 .. n+1,
// n = ceil(2 log10(f_high / f_low)) (half a decade apart, one extra component beyond each end), each with the same
// variance sigma_i^2 = B^2 ln(sqrt 10) / pi. Sum over log-spaced Lorentzians 4 s^2 T / (1 + (2 pi f T)^2) with
// spacing ln r gives s^2 / (f ln r) ~ one-sided B^2 / (pi f), hence that variance. The closed-form ADEV of the sum
// stays within 5 % of 0.664 B for tau in [2.5 / (2 pi f_high), 1 / (2 pi f_low)] (checked in the test).
// Each component uses the exact GM discretisation and starts stationary. Cost: n + 3 GM updates per channel.
// Point samples alias the components above Nyquist: keep f_high <= f_s / 10 for the plateau to reach down to
// 2.5 / (2 pi f_high) (above that the short-tau ADEV is lifted, as for any unfiltered sampled noise).
// Cannot represent: 1/f noise outside [f_low, f_high] (below f_low the PSD flattens, above f_high it falls as
// 1/f^2), non-Gaussian flicker; the ADEV ripple from the half-decade spacing is < 1 %.
#pragma once

#include <vector>

#include "sim/effects/params.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::sim {

struct FlickerParams {
    double b_dps = 0.0;           ///< gyro bias instability B [deg/s] (ADEV floor 0.664 B)
    std::array<double, 3> b_g{};  ///< accel x, y, z bias instability B [g]
    double f_low_hz = 1e-3;       ///< lowest frequency of the 1/f band [Hz]
    double f_high_hz = 1.0;       ///< highest frequency of the 1/f band [Hz]

    template <class V>
    void visit(V& v) {
        v.field("b_dps", b_dps, "deg/s", "gyro bias instability B (ADEV plateau 0.664 B)", Check::nonneg);
        v.field("b_g", b_g, "g", "accel x, y, z bias instability B", Check::nonneg);
        v.field("f_low_hz", f_low_hz, "Hz", "lower end of the 1/f band", Check::positive);
        v.field("f_high_hz", f_high_hz, "Hz", "upper end of the 1/f band", Check::positive);
    }
    void validate(const TomlReader& r) const {
        if (!(f_high_hz > f_low_hz)) r.fail("f_high_hz", "expected f_high_hz > f_low_hz [Hz]");
    }
};

class Flicker : public EffectWith<Flicker, FlickerParams> {
public:
    using Params = FlickerParams;
    static constexpr std::string_view kName = "flicker";
    static constexpr Stage kStage = Stage::physical;
    static constexpr std::string_view kEquation =
        "b = sum_i GM(sigma_i, T_i), T_i = 1/(2 pi f_low 10^(i/2)), sigma_i^2 = B^2 ln(sqrt 10)/pi";
    static constexpr std::string_view kSummary = "bias instability, 1/f noise, ADEV plateau 0.664 B (E3)";

    explicit Flicker(const Params& params);
    void reset(std::uint64_t seed) override;
    void apply(ChannelValues& values, const EffectContext& ctx) override;

    /// Correlation times of the components [s], longest first.
    const std::vector<double>& component_tau_s() const { return tau_s_; }
    /// Standard deviation of each component per unit B [-]: sigma_i = B * component_sigma_per_b().
    static double component_sigma_per_b();

private:
    std::vector<double> tau_s_;
    std::vector<Rng> rng_;
    std::vector<double> state_;  // channel-major: state_[c * n + i]
    // phi_i = exp(-dt / tau_i) and sqrt(1 - phi_i^2) for the last dt: the instants are evenly spaced, so these are
    // computed once per run rather than once per conversion and component.
    double cached_dt_s_ = -1.0;
    std::vector<double> phi_, innovation_;
};

}  // namespace driftlab::sim
