// E4 rate_random_walk against its closed forms: Var b(t) = K^2 t over replicates, ADEV K sqrt(tau/3) (+1/2 slope).
#include "sim/effects/rate_random_walk.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

RateRandomWalkParams params(double k) {
    RateRandomWalkParams p;
    p.k_dps_per_sqrt_s = k;
    p.k_g_per_sqrt_s = {k, k, k};
    return p;
}

TEST(RateRandomWalk, VarianceGrowsAsKSquaredT) {
    const double k = 0.01;
    RateRandomWalk rrw(params(k));
    const std::size_t replicates = 4000;
    std::vector<double> at_20s, at_80s;
    for (std::size_t r = 0; r < replicates; ++r) {
        rrw.reset(1000 + r);
        const auto y = test::run_added(rrw, 161, 0.5);  // t = 0 .. 80 s
        at_20s.push_back(y[0][40]);
        at_80s.push_back(y[2][160]);
    }
    // Relative sd of a variance estimate from n Gaussian replicates: sqrt(2/n); 5 sigmas.
    const double tol = 5.0 * std::sqrt(2.0 / static_cast<double>(replicates));
    EXPECT_NEAR(test::variance(at_20s) / (k * k * 20.0), 1.0, tol);
    EXPECT_NEAR(test::variance(at_80s) / (k * k * 80.0), 1.0, tol);
}

TEST(RateRandomWalk, StartsAtZeroAndIsExactForUnevenSteps) {
    const double k = 0.2;
    RateRandomWalk rrw(params(k));
    std::vector<double> end;
    for (std::size_t r = 0; r < 4000; ++r) {
        rrw.reset(r);
        EffectContext ctx;
        ChannelValues v{};
        rrw.apply(v, ctx);  // dt = 0
        EXPECT_EQ(v[1], 0.0);
        for (double dt : {0.1, 2.9, 1.0}) {  // 4 s in uneven steps
            ctx.dt_s = dt;
            v = {};
            rrw.apply(v, ctx);
        }
        end.push_back(v[1]);
    }
    EXPECT_NEAR(test::variance(end) / (k * k * 4.0), 1.0, 5.0 * std::sqrt(2.0 / 4000.0));
}

TEST(RateRandomWalk, AllanDeviationFollowsKSqrtTauOverThree) {
    const double k = 1e-3;
    RateRandomWalk rrw(params(k));
    rrw.reset(77);
    const auto y = test::run_added(rrw, 1 << 17, 1.0);
    // Point samples of a random walk: AVAR(m) = K^2 tau/3 (1 + 1/(2 m^2)) exactly (difference of m-means).
    auto expected = [&](double m) { return k * k * m / 3.0 * (1.0 + 1.0 / (2.0 * m * m)); };
    double avar16 = 0.0, avar256 = 0.0;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        avar16 += test::oavar(y[c], 1.0, 16) / 4.0;
        avar256 += test::oavar(y[c], 1.0, 256) / 4.0;
    }
    // EDF of RRW at N/m = 512 is ~ 2 (N/m)^(1/2)-ish per channel; 4 channels: ADEV within ~25 % at tau = 256.
    EXPECT_NEAR(std::sqrt(avar16 / expected(16)), 1.0, 0.15);
    EXPECT_NEAR(std::sqrt(avar256 / expected(256)), 1.0, 0.3);
    const double slope = 0.5 * std::log(avar256 / avar16) / std::log(16.0);
    EXPECT_NEAR(slope, 0.5, 0.12);
}

}  // namespace
}  // namespace driftlab::sim
