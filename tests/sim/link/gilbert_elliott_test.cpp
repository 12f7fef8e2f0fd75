// Gilbert–Elliott loss statistics against the closed form of the two-state chain.
#include "sim/link/gilbert_elliott.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace driftlab::sim {
namespace {

struct LossStats {
    double loss_rate;
    double mean_burst;
};

LossStats run(const PacketLossParams& p, int n, std::uint64_t seed) {
    GilbertElliott ge(p, Rng(seed, 5));
    int lost = 0, bursts = 0;
    bool prev = false;
    for (int i = 0; i < n; ++i) {
        const bool l = ge.step_lost();
        lost += l;
        bursts += l && !prev;
        prev = l;
    }
    return {static_cast<double>(lost) / n, static_cast<double>(lost) / bursts};
}

TEST(GilbertElliott, GilbertCaseLossRateIsPOverPPlusRAndBurstsAverageOneOverR) {
    PacketLossParams p;
    p.p_good_to_bad = 0.01;
    p.p_bad_to_good = 0.25;
    const int n = 2000000;
    const LossStats s = run(p, n, 3);
    const double rate = 0.01 / 0.26;
    // Standard error of a Markov-chain mean: sqrt(rate(1-rate)/n · (1+lambda)/(1-lambda)), lambda = 1-p-r.
    const double lambda = 1.0 - 0.01 - 0.25;
    const double se = std::sqrt(rate * (1 - rate) / n * (1 + lambda) / (1 - lambda));
    EXPECT_NEAR(s.loss_rate, rate, 4 * se);
    // Bursts are geometric(r): mean 1/r = 4, sd sqrt(1-r)/r, about n·rate/4 = 19000 bursts.
    EXPECT_NEAR(s.mean_burst, 4.0, 4 * std::sqrt(0.75) / 0.25 / std::sqrt(n * rate / 4.0));
}

TEST(GilbertElliott, ElliottCaseLossRateMixesTheStateLossProbabilities) {
    PacketLossParams p;
    p.p_good_to_bad = 0.02;
    p.p_bad_to_good = 0.1;
    p.loss_in_good = 0.01;
    p.loss_in_bad = 0.6;
    const int n = 2000000;
    const LossStats s = run(p, n, 4);
    const double expected = (0.1 * 0.01 + 0.02 * 0.6) / 0.12;
    EXPECT_NEAR(s.loss_rate, expected, 0.03 * expected);
}

TEST(GilbertElliott, IndependentLossWhenTheStatesAgree) {
    PacketLossParams p;
    p.p_good_to_bad = 0.5;
    p.p_bad_to_good = 0.5;
    p.loss_in_good = 0.1;
    p.loss_in_bad = 0.1;
    const LossStats s = run(p, 1000000, 5);
    EXPECT_NEAR(s.loss_rate, 0.1, 4 * std::sqrt(0.09 / 1e6));
    EXPECT_NEAR(s.mean_burst, 1.0 / 0.9, 0.01);  // geometric runs of an i.i.d. Bernoulli(0.1)
}

TEST(GilbertElliott, FrameUnitLosesWholePacketsAndCountsThem) {
    PacketLossParams p;
    p.p_good_to_bad = 0.1;
    p.p_bad_to_good = 0.5;
    GilbertElliott ge(p, Rng(1, 1));
    LinkCounters c;
    int lost = 0;
    for (int i = 0; i < 1000; ++i) {
        Packet pk;
        pk.bytes.assign(33, TimedByte{0.0, 0xAA});
        ge.process(pk, c);
        if (pk.damaged) {
            EXPECT_TRUE(pk.bytes.empty());
            ++lost;
        } else {
            EXPECT_EQ(pk.bytes.size(), 33u);
        }
    }
    EXPECT_EQ(c.packets_lost, static_cast<std::uint64_t>(lost));
    EXPECT_EQ(c.bytes_lost, 33u * lost);
    EXPECT_GT(lost, 0);
}

}  // namespace
}  // namespace driftlab::sim
