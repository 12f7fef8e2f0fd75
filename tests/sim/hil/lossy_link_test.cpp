// A lossy link: the host's lost-frame count (seq gaps) equals exactly what the link model destroyed, and no
// damaged value reaches the log. In stream mode the firmware's outputs do not depend on the host, so a clean run
// with the same seed is the reference for every row the lossy run logged.
#include <map>

#include <gtest/gtest.h>

#include "tests/sim/hil/hil_test_support.hpp"

namespace driftlab::sim {
namespace {

using testing::preset;
using testing::run_into_memory;

HilOptions stream_run(std::uint64_t seed) {
    HilOptions o = preset(Preset::fig2, seed);
    o.model.firmware.mode = static_cast<std::uint8_t>(proto::OutputMode::stream);
    o.duration_s = 300.0;
    return o;
}

void make_lossy(DirectionParams& d) {
    d.byte_error_rate = 5e-4;
    d.byte_drop_rate = 5e-4;
    d.packet_loss.unit = LossUnit::frame;
    d.packet_loss.p_good_to_bad = 0.01;
    d.packet_loss.p_bad_to_good = 0.3;
}

TEST(LossyLink, LostFramesFromSeqGapsEqualFramesTheLinkDamaged) {
    HilOptions o = stream_run(5);
    make_lossy(o.model.link.to_host);
    const auto run = run_into_memory(o);
    const HilSummary& s = run.summary;
    ASSERT_GT(s.to_host.packets_damaged, 50u);
    EXPECT_EQ(s.host.frames_lost, s.to_host.packets_damaged);
    // Every frame the firmware sent is either received or counted lost: nothing is left in flight at the end.
    EXPECT_EQ(s.host.frames_received + s.host.frames_lost, s.to_host.packets_sent);
    EXPECT_EQ(s.host.last_seq + 1, s.to_host.packets_sent);
    // Damaged frames were rejected by the decoder (CRC, length) rather than delivered.
    EXPECT_GT(s.decoder.bad_crc + s.decoder.bad_length, 0u);
}

TEST(LossyLink, NoDamagedValueReachesTheLog) {
    HilOptions clean = stream_run(6);
    HilOptions lossy = clean;
    make_lossy(lossy.model.link.to_host);
    const auto ref = run_into_memory(clean);
    const auto got = run_into_memory(lossy);
    std::map<std::uint64_t, const HilRecord*> by_tick;
    for (const auto& r : ref.rows) by_tick[r.tick] = &r;
    ASSERT_LT(got.rows.size(), ref.rows.size());
    std::size_t compared = 0;
    for (const auto& r : got.rows) {
        if (r.n_window < kFig2Window) continue;  // the handshake may end at another time than in the clean run
        const auto it = by_tick.find(r.tick);
        ASSERT_NE(it, by_tick.end()) << "a logged tick the firmware never produced: " << r.tick;
        EXPECT_EQ(r.value_counts, it->second->value_counts) << "tick " << r.tick;
        EXPECT_EQ(r.raw_counts, it->second->raw_counts) << "tick " << r.tick;
        ++compared;
    }
    EXPECT_GT(compared, got.rows.size() * 9 / 10);
}

TEST(LossyLink, LostPollsAreTheDamagedRequestsNotRetriedOnes) {
    HilOptions o = preset(Preset::fig2, 7);
    o.duration_s = 300.0;
    make_lossy(o.model.link.to_firmware);
    const auto run = run_into_memory(o);
    const HilSummary& s = run.summary;
    ASSERT_GT(s.to_firmware.packets_damaged, 20u);
    // Only the host->firmware direction is lossy: a damaged handshake request costs one retry, a damaged POLL one
    // missing SAMPLE.
    EXPECT_EQ(s.host.frames_lost, 0u);
    EXPECT_EQ(s.host.samples_received, s.host.polls_sent - (s.to_firmware.packets_damaged - s.host.retries));
    EXPECT_GT(s.status.rx_bad_crc + s.status.rx_bad_length + s.status.rx_unknown_type, 0);
}

}  // namespace
}  // namespace driftlab::sim
