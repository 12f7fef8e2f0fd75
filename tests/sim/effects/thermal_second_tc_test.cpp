// E1 thermal_second_tc against C3 (1 - exp(-t/T2)): values at t = 0, T2, many T2, and the log-linear decay.
#include "sim/effects/thermal_second_tc.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

TEST(ThermalSecondTc, FollowsSecondExponentialPerChannel) {
    ThermalSecondTcParams p;
    p.c3_dps = 0.3;
    p.c3_g = {-0.01, 0.02, 0.005};
    p.t2_s = {600.0, 1200.0, 2400.0, 3600.0};
    ThermalSecondTc e(p);
    const ChannelValues c3 = {0.3, -0.01, 0.02, 0.005};
    for (double t : {0.0, 600.0, 1200.0, 5000.0, 1e6}) {
        EffectContext ctx;
        ctx.t_s = t;
        ChannelValues v{};
        e.apply(v, ctx);
        for (std::size_t c = 0; c < kChannelCount; ++c) {
            EXPECT_NEAR(v[c], c3[c] * (1.0 - std::exp(-t / p.t2_s[c])), 1e-15) << "t " << t << " ch " << c;
        }
    }
}

TEST(ThermalSecondTc, RemainingGapDecaysWithSlopeMinusOneOverT2) {
    ThermalSecondTcParams p;
    p.c3_dps = 1.0;
    p.t2_s.fill(900.0);
    ThermalSecondTc e(p);
    // ln(C3 - y(t)) is a line of slope -1/T2: fit it by least squares over 0..3 T2.
    double st = 0, sy = 0, stt = 0, sty = 0, n = 0;
    for (double t = 0.0; t <= 2700.0; t += 30.0) {
        EffectContext ctx;
        ctx.t_s = t;
        ChannelValues v{};
        e.apply(v, ctx);
        const double ly = std::log(1.0 - v[0]);
        st += t;
        sy += ly;
        stt += t * t;
        sty += t * ly;
        n += 1;
    }
    const double slope = (n * sty - st * sy) / (n * stt - st * st);
    EXPECT_NEAR(slope, -1.0 / 900.0, 1e-9);
}

}  // namespace
}  // namespace driftlab::sim
