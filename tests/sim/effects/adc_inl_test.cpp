// E7 adc_inl: the added error is the Legendre bow/S curve: P2 = 1 at both ends and -1/2 at mid-scale, P3 odd
// about mid-scale with extremes +-1 at the ends, P4 = 3/8 at mid-scale.
#include "sim/effects/adc_inl.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

double added(AdcInl& e, double x) {
    ChannelValues v = {x, x, x, x};
    e.apply(v, EffectContext{});
    return v[2] - x;
}

TEST(AdcInl, BowIsLegendreP2AcrossTheCodes) {
    AdcInlParams p;
    p.a2_lsb = 1.5;
    AdcInl e(p);
    EXPECT_NEAR(added(e, 0.0), 1.5, 1e-12);
    EXPECT_NEAR(added(e, 1023.0), 1.5, 1e-12);
    EXPECT_NEAR(added(e, 511.5), -0.75, 1e-12);
    for (double x = 0.0; x <= 1023.0; x += 31.0) {
        const double u = 2.0 * x / 1023.0 - 1.0;
        EXPECT_NEAR(added(e, x), 1.5 * (1.5 * u * u - 0.5), 1e-12) << x;
    }
}

TEST(AdcInl, SCurveIsOddAboutMidScaleAndP4HasItsCentreValue) {
    AdcInlParams p;
    p.a3_lsb = 0.8;
    AdcInl s(p);
    for (double d : {10.0, 200.0, 511.5}) EXPECT_NEAR(added(s, 511.5 + d), -added(s, 511.5 - d), 1e-12);
    EXPECT_NEAR(added(s, 1023.0), 0.8, 1e-12);
    AdcInlParams q;
    q.a4_lsb = 1.0;
    AdcInl f(q);
    EXPECT_NEAR(added(f, 511.5), 3.0 / 8.0, 1e-12);
    EXPECT_NEAR(added(f, 0.0), 1.0, 1e-12);
}

TEST(AdcInl, InputsBeyondTheRangeUseTheEndValue) {
    AdcInlParams p;
    p.a2_lsb = 1.0;
    AdcInl e(p);
    EXPECT_NEAR(added(e, -50.0), 1.0, 1e-12);
    EXPECT_NEAR(added(e, 1500.0), 1.0, 1e-12);
}

}  // namespace
}  // namespace driftlab::sim
