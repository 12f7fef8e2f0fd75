// E4 rate_random_walk: Brownian bias (IEEE 952 rate random walk K), physical stage; docs/effects.md.
//
// Equation (exact for Brownian motion at any dt):  b_k = b_{k-1} + K sqrt(dt) eta_k,  b = 0 at power-on,  y = u + b;
//   the first instant's dt is ctx.since_power_on_s (the sensor chain sets it; callers that leave it 0 start the
//   walk at their first instant).
//   Var b(t) = K^2 t;  ADEV K sqrt(tau/3) (slope +1/2);  IEEE 952 two-sided PSD (K / 2 pi)^2 / f^2
//   (gap-method.md section 3, E4).
// Units: K in [deg/s/sqrt(s)] for the gyro (= deg/s^2/sqrt(Hz), Kalibr's gyroscope_random_walk in degrees) and
// [g/sqrt(s)] for the accelerometers.
// Cannot represent: a bounded wander (use gauss_markov), drift that repeats across power-ons (thermal_second_tc).
#pragma once

#include <vector>

#include "sim/effects/params.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::sim {

struct RateRandomWalkParams {
    double k_dps_per_sqrt_s = 0.0;           ///< gyro K [deg/s/sqrt(s)]
    std::array<double, 3> k_g_per_sqrt_s{};  ///< accel x, y, z K [g/sqrt(s)]

    template <class V>
    void visit(V& v) {
        v.field("k_dps_per_sqrt_s", k_dps_per_sqrt_s, "deg/s/sqrt(s)", "gyro rate random walk K", Check::nonneg);
        v.field("k_g_per_sqrt_s", k_g_per_sqrt_s, "g/sqrt(s)", "accel x, y, z random walk K", Check::nonneg);
    }
};

class RateRandomWalk : public EffectWith<RateRandomWalk, RateRandomWalkParams> {
public:
    using Params = RateRandomWalkParams;
    static constexpr std::string_view kName = "rate_random_walk";
    static constexpr Stage kStage = Stage::physical;
    static constexpr std::string_view kEquation = "b_k = b_{k-1} + K sqrt(dt) eta, b_0 = 0";
    static constexpr std::string_view kSummary = "Brownian bias, rate random walk K (E4)";

    explicit RateRandomWalk(const Params& params) : EffectWith(params) { reset(0); }
    void reset(std::uint64_t seed) override;
    void apply(ChannelValues& values, const EffectContext& ctx) override;

private:
    std::vector<Rng> rng_;
    ChannelValues bias_{};
};

}  // namespace driftlab::sim
