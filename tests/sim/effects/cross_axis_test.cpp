// E9 cross_axis: the accel output equals (I + S/100) a, checked against an Eigen matrix product.
#include "sim/effects/cross_axis.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "effect_test_support.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::sim {
namespace {

TEST(CrossAxis, OutputIsMatrixProductOfTrueAcceleration) {
    CrossAxisParams p;
    p.matrix_pct = {{{0.5, 2.0, -1.0}, {1.5, 0.0, 3.0}, {-2.5, 0.7, -0.3}}};
    CrossAxis e(p);
    Eigen::Matrix3d m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m(i, j) = (i == j ? 1.0 : 0.0) + p.matrix_pct[i][j] / 100.0;
    Rng rng(9, 0);
    for (int trial = 0; trial < 100; ++trial) {
        const Eigen::Vector3d a(rng.normal(), rng.normal(), rng.normal());
        EffectContext ctx;
        ctx.true_physical = {rng.normal(), a.x(), a.y(), a.z()};
        ChannelValues v = ctx.true_physical;
        e.apply(v, ctx);
        const Eigen::Vector3d expected = m * a;
        EXPECT_EQ(v[0], ctx.true_physical[0]);  // the gyro is not an accel axis
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(v[static_cast<std::size_t>(i) + 1], expected(i), 1e-14);
    }
}

TEST(CrossAxis, PerConversionTouchesOnlyTheConvertedAxis) {
    CrossAxisParams p;
    p.matrix_pct = {{{0.0, 1.0, 1.0}, {1.0, 0.0, 1.0}, {1.0, 1.0, 0.0}}};
    CrossAxis e(p);
    EffectContext ctx;
    ctx.true_physical = {0.0, 1.0, 1.0, 1.0};
    ctx.channel = Channel::accel_y;
    ChannelValues v{};
    e.apply(v, ctx);
    EXPECT_EQ(v, (ChannelValues{0.0, 0.0, 0.02, 0.0}));
    ctx.channel = Channel::gyro;
    v = {};
    e.apply(v, ctx);
    EXPECT_EQ(v, (ChannelValues{}));
}

}  // namespace
}  // namespace driftlab::sim
