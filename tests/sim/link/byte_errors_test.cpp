// Byte corruption and byte drops: rates against the binomial expectation, exact counting, changed values.
#include "sim/link/byte_errors.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "sim/link/dropped_bytes.hpp"

namespace driftlab::sim {
namespace {

TEST(ByteErrors, CorruptsAtTheRateAndEveryCorruptedByteDiffers) {
    ByteErrors e(0.01, Rng(9, 2));
    LinkCounters c;
    const int n = 500000;
    Packet p;
    for (int i = 0; i < n; ++i) p.bytes.push_back({0.0, static_cast<std::uint8_t>(i)});
    e.process(p, c);
    int changed = 0;
    for (int i = 0; i < n; ++i) changed += p.bytes[i].value != static_cast<std::uint8_t>(i);
    EXPECT_EQ(static_cast<std::uint64_t>(changed), c.bytes_corrupted);
    EXPECT_NEAR(changed, 0.01 * n, 4 * std::sqrt(n * 0.01 * 0.99));
    EXPECT_TRUE(p.damaged);
}

TEST(DroppedBytes, DropsAtTheRateKeepsTheOthersInOrder) {
    DroppedBytes d(0.05, Rng(9, 3));
    LinkCounters c;
    const int n = 200000;
    Packet p;
    for (int i = 0; i < n; ++i) p.bytes.push_back({static_cast<double>(i), 0});
    d.process(p, c);
    EXPECT_EQ(c.bytes_dropped + p.bytes.size(), static_cast<std::uint64_t>(n));
    EXPECT_NEAR(static_cast<double>(c.bytes_dropped), 0.05 * n, 4 * std::sqrt(n * 0.05 * 0.95));
    for (std::size_t i = 1; i < p.bytes.size(); ++i) ASSERT_LT(p.bytes[i - 1].t_s, p.bytes[i].t_s);
}

TEST(LinkDirection, CountsEveryDamagedPacketOnceWhateverDamagedIt) {
    DirectionParams params;
    params.byte_error_rate = 0.002;
    params.byte_drop_rate = 0.002;
    params.packet_loss.p_good_to_bad = 0.02;
    params.packet_loss.p_bad_to_good = 0.5;
    LinkDirection d(1e6, params, 17, 0x200);
    std::uint64_t damaged = 0, delivered_intact = 0;
    std::vector<std::uint8_t> frame(33);
    for (int i = 0; i < 20000; ++i) {
        for (std::size_t k = 0; k < frame.size(); ++k) frame[k] = static_cast<std::uint8_t>(i + k);
        d.send(i * 1e-3, frame);
        std::vector<std::uint8_t> out;
        d.deliver_until(i * 1e-3 + 1.0, out);
        if (out == frame)
            ++delivered_intact;
        else
            ++damaged;
    }
    EXPECT_EQ(d.counters().packets_damaged, damaged);
    EXPECT_EQ(d.counters().packets_sent, delivered_intact + damaged);
    EXPECT_GT(d.counters().packets_lost, 0u);
    EXPECT_GT(d.counters().bytes_corrupted, 0u);
    EXPECT_GT(d.counters().bytes_dropped, 0u);
}

}  // namespace
}  // namespace driftlab::sim
