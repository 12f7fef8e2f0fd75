// E5 gauss_markov: first-order Gauss-Markov (exponentially correlated) bias, physical stage; docs/effects.md.
//
// Equation (exact discretisation, any dt; Maybeck 4-114, as in RotorS and NaveGo):
//   b_k = phi * b_{k-1} + sigma * sqrt(1 - phi^2) * eta_k,   phi = exp(-dt / tau),   eta ~ N(0, 1)
//   y = u + b.   Stationary variance sigma^2, autocorrelation sigma^2 exp(-|lag| / tau),
//   ADEV peak 0.618 sigma at 1.89 tau (gap-method.md section 4, E5).
// The state starts from the stationary distribution b_0 ~ N(0, sigma^2), so the process is stationary from power-on
// (anchors that start at 0 show a spurious variance ramp over the first tau).
// Cannot represent: non-Gaussian bias jumps (mode hops), a temperature-dependent sigma or tau.
#pragma once

#include <vector>

#include "sim/effects/params.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::sim {

struct GaussMarkovParams {
    double sigma_dps = 0.0;                           ///< gyro stationary std [deg/s]
    std::array<double, 3> sigma_g{};                  ///< accel x, y, z stationary std [g]
    ChannelValues tau_s{100.0, 100.0, 100.0, 100.0};  ///< correlation time per channel [s]

    template <class V>
    void visit(V& v) {
        v.field("sigma_dps", sigma_dps, "deg/s", "gyro stationary standard deviation", Check::nonneg);
        v.field("sigma_g", sigma_g, "g", "accel x, y, z stationary standard deviation", Check::nonneg);
        v.field("tau_s", tau_s, "s", "correlation time per channel (scalar or 4 values)", Check::positive);
    }
};

class GaussMarkov : public EffectWith<GaussMarkov, GaussMarkovParams> {
public:
    using Params = GaussMarkovParams;
    static constexpr std::string_view kName = "gauss_markov";
    static constexpr Stage kStage = Stage::physical;
    static constexpr std::string_view kEquation = "b_k = phi b_{k-1} + sigma sqrt(1-phi^2) eta, phi = exp(-dt/tau)";
    static constexpr std::string_view kSummary = "first-order Gauss-Markov bias (E5)";

    explicit GaussMarkov(const Params& params) : EffectWith(params) { reset(0); }
    void reset(std::uint64_t seed) override;
    void apply(ChannelValues& values, const EffectContext& ctx) override;

private:
    std::vector<Rng> rng_;
    ChannelValues bias_{};
};

}  // namespace driftlab::sim
