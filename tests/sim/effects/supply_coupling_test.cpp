// E8 supply_coupling: ripple and drift reach each channel as (r_c - r_adc) v dV / V_nom + p_c dV.
#include "sim/effects/supply_coupling.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

TEST(SupplyCoupling, RippleAmplitudeFollowsRatiometricMismatchAndDcLevel) {
    SupplyCouplingParams p;
    p.sensor_ratiometric = {0.0, 1.0, 0.0, 0.5};
    p.adc_ratiometric = 1.0;
    p.pickup_v_per_v = {0.0, 0.0, 0.01, 0.0};
    p.ripple_v = 0.02;
    p.ripple_hz = 100.0;
    SupplyCoupling e(p);
    const ChannelValues dc = {2.5, 2.5, 1.0, 3.0};
    const double fs = 1000.0;
    const std::size_t n = 1000;
    const auto y = test::run_added(e, n, 1.0 / fs, dc);
    const auto t = test::time_grid(n, 1.0 / fs);
    // Channel 0: fully non-ratiometric sensor on a ratiometric ADC: -(v / V_nom) A_r.
    EXPECT_NEAR(test::fit_tone(y[0], t, 100.0).amplitude, 2.5 / 5.0 * 0.02, 1e-12);
    for (double v : y[1]) EXPECT_NEAR(v, 0.0, 1e-15);  // matched: no coupling
    // Channel 2: (0 - 1) * 1.0 / 5 + 0.01 pickup.
    EXPECT_NEAR(test::fit_tone(y[2], t, 100.0).amplitude, std::abs(-1.0 / 5.0 + 0.01) * 0.02, 1e-12);
    EXPECT_NEAR(test::fit_tone(y[3], t, 100.0).amplitude, 0.5 * 3.0 / 5.0 * 0.02, 1e-12);
}

TEST(SupplyCoupling, RegulatorDriftAndModelledSupplyShiftTheOutput) {
    SupplyCouplingParams p;
    p.sensor_ratiometric = {0.0, 0.0, 0.0, 0.0};
    p.drift_v = -0.05;
    p.drift_tau_s = 100.0;
    SupplyCoupling e(p);
    EffectContext ctx;
    ctx.t_s = 100.0;
    ctx.supply_v = 5.1;
    ChannelValues v = {2.5, 2.5, 2.5, 2.5};
    e.apply(v, ctx);
    const double dv = 0.1 - 0.05 * (1.0 - std::exp(-1.0));
    EXPECT_NEAR(e.supply_deviation_v(ctx), dv, 1e-15);
    EXPECT_NEAR(v[2], 2.5 * (1.0 - dv / 5.0), 1e-15);
}

}  // namespace
}  // namespace driftlab::sim
