// 8N1 timing: a byte takes 10 bit times, back-to-back bytes queue behind each other, the line idles in gaps.
#include "sim/link/baud_timing.hpp"

#include <gtest/gtest.h>

#include "sim/link/link.hpp"

namespace driftlab::sim {
namespace {

std::vector<double> arrivals(LinkDirection& d, double until_s) {
    std::vector<double> t;
    while (auto next = d.next_arrival_s()) {
        if (*next > until_s) break;
        t.push_back(*next);
        std::vector<std::uint8_t> out;
        d.deliver_until(*next, out);
        for (std::size_t i = 1; i < out.size(); ++i) t.push_back(*next);
    }
    return t;
}

TEST(BaudTiming, BytesArriveTenBitTimesApartFromTheSendTime) {
    LinkDirection d(9600.0, DirectionParams{}, 1, 0);
    const std::uint8_t frame[5] = {1, 2, 3, 4, 5};
    d.send(2.0, frame);
    const auto t = arrivals(d, 10.0);
    ASSERT_EQ(t.size(), 5u);
    for (std::size_t k = 0; k < 5; ++k) EXPECT_NEAR(t[k], 2.0 + (k + 1) * 10.0 / 9600.0, 1e-12) << k;
}

TEST(BaudTiming, APacketSentWhileTheLineIsBusyWaitsForIt) {
    LinkDirection d(1000.0, DirectionParams{}, 1, 0);  // 10 ms per byte
    const std::uint8_t a[3] = {1, 2, 3}, b[2] = {4, 5};
    d.send(0.0, a);    // occupies the line until 30 ms
    d.send(0.005, b);  // must wait: 40 ms and 50 ms
    d.send(1.0, b);    // line idle again: 1.01 s and 1.02 s
    const auto t = arrivals(d, 10.0);
    const double expected[] = {0.01, 0.02, 0.03, 0.04, 0.05, 1.01, 1.02};
    ASSERT_EQ(t.size(), 7u);
    for (std::size_t k = 0; k < 7; ++k) EXPECT_NEAR(t[k], expected[k], 1e-12) << k;
}

TEST(BaudTiming, LatencyShiftsEveryArrivalAndKeepsOrder) {
    DirectionParams p;
    p.latency_s = 0.25;
    LinkDirection d(9600.0, p, 1, 0);
    const std::uint8_t frame[33] = {};
    d.send(0.0, frame);
    const auto t = arrivals(d, 10.0);
    ASSERT_EQ(t.size(), 33u);
    EXPECT_NEAR(t.front(), 0.25 + 10.0 / 9600.0, 1e-12);
    EXPECT_NEAR(t.back(), 0.25 + 33 * 10.0 / 9600.0, 1e-12);
}

TEST(BaudTiming, DeliverUntilHandsOverOnlyBytesDueByThen) {
    LinkDirection d(1000.0, DirectionParams{}, 1, 0);
    const std::uint8_t a[4] = {10, 20, 30, 40};
    d.send(0.0, a);
    std::vector<std::uint8_t> out;
    d.deliver_until(0.025, out);
    EXPECT_EQ(out, (std::vector<std::uint8_t>{10, 20}));
    d.deliver_until(1.0, out);
    EXPECT_EQ(out, (std::vector<std::uint8_t>{10, 20, 30, 40}));
    EXPECT_FALSE(d.next_arrival_s().has_value());
    EXPECT_EQ(d.counters().bytes_delivered, 4u);
}

}  // namespace
}  // namespace driftlab::sim
