// The link in the gap diagnosis: frame slots from sequence numbers, the exact likelihood of a slot pattern against
// closed forms, and the candidates found on logs whose frames a known chain took.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "host/gap/link_loss.hpp"

namespace driftlab::host::gap {
namespace {

// A log of `lost.size()` frame slots at 1 s, the rows of the slots not lost.
LogData log_of(const std::vector<std::uint8_t>& lost) {
    LogData log;
    log.source_name = "link test";
    for (std::size_t k = 0; k < lost.size(); ++k) {
        if (lost[k]) continue;
        log.t_s.push_back(static_cast<double>(k + 1));
        log.seq.push_back(k);
    }
    for (auto& c : log.counts) c.assign(log.t_s.size(), 512.0);
    return log;
}

sim::LinkParams lossless() { return {}; }

TEST(LinkLoss, SlotsComeFromTheSequenceNumbersAndAJoinIsNotObserved) {
    LogData log = log_of({0, 0, 0, 1, 1, 0, 0});
    const FrameSlots s = frame_slots(log, BatteryOptions{});
    EXPECT_EQ(s.lost, (std::vector<std::uint8_t>{0, 0, 0, 1, 1, 0, 0}));
    EXPECT_EQ(s.observed, (std::vector<std::uint8_t>{1, 1, 1, 1, 1, 1, 1}));
    EXPECT_EQ(s.spacing_off[0] + s.spacing_off[1], 0.0);
    log.cuts.push_back({3, 3.5, 5.5, 2, "--exclude"});  // the user left slots 3 and 4 out: not lost, not seen
    const FrameSlots cut = frame_slots(log, BatteryOptions{});
    EXPECT_EQ(cut.observed, (std::vector<std::uint8_t>{1, 1, 1, 0, 0, 1, 1}));
}

// Memoryless loss: k ln q + (n - k) ln(1 - q). A fully seen Gilbert chain: its stationary start and each transition.
TEST(LinkLoss, TheLikelihoodOfASlotPatternIsTheClosedForm) {
    const std::vector<std::uint8_t> lost{0, 1, 0, 0, 1, 1, 1, 0, 0, 0};
    const FrameSlots s = frame_slots(log_of(lost), BatteryOptions{});
    const std::vector<bool> all(lost.size(), true);
    FrameLoss bernoulli;
    bernoulli.corrupted = 0.2;
    EXPECT_NEAR(slot_log_likelihood(bernoulli, s, all), 4 * std::log(0.2) + 6 * std::log(0.8), 1e-12);
    FrameLoss chain;
    chain.chain = {sim::LossUnit::frame, 0.3, 0.6, 0.0, 1.0};
    const double p = 0.3, r = 0.6;
    // G, B, G, G, B, B, B, G, G, G: start G (1 - p/(p+r)), then GB GG... transitions.
    const double expected = std::log(r / (p + r)) + std::log(p) + std::log(r) + std::log(1 - p) + std::log(p) +
                            2 * std::log(1 - r) + std::log(r) + 2 * std::log(1 - p);
    EXPECT_NEAR(slot_log_likelihood(chain, s, all), expected, 1e-12);
    EXPECT_EQ(slot_log_likelihood(FrameLoss{}, s, all), -INFINITY);  // a lossless link cannot make it
}

TEST(LinkLoss, BurstyLossIsNamedPacketLossWithTheChainsParameters) {
    FrameLoss truth;
    truth.chain = {sim::LossUnit::frame, 0.01, 0.25, 0.0, 1.0};
    const LogData log = log_of(simulate_slots(truth, 20000, 3));
    const LinkFindings f = diagnose_link(log, lossless(), BatteryOptions{}, 40, 5, 0.05, true);
    ASSERT_FALSE(f.located.empty());
    ASSERT_TRUE(f.added);
    const Explanation& e = f.tried[*f.added];
    EXPECT_EQ(e.effect, "packet_loss");
    EXPECT_NEAR(e.estimate()[0].second, 0.01, 0.002);
    EXPECT_NEAR(e.estimate()[1].second, 0.25, 0.04);
}

TEST(LinkLoss, SingleCorruptedFramesAreNamedByteErrors) {
    FrameLoss truth;
    truth.corrupted = 0.02;
    const LogData log = log_of(simulate_slots(truth, 20000, 4));
    const LinkFindings f = diagnose_link(log, lossless(), BatteryOptions{}, 40, 5, 0.05, true);
    ASSERT_TRUE(f.added);
    const Explanation& e = f.tried[*f.added];
    EXPECT_EQ(e.effect, "byte_errors");
    const double frame = 1.0 - std::pow(1.0 - e.estimate()[0].second, static_cast<double>(sample_frame_bytes()));
    EXPECT_NEAR(frame, 0.02, 0.003);
}

// The unit's own link explains its losses: nothing located (at a tenth of 5 %; three logs, at most one flagged).
TEST(LinkLoss, ALinkThatLosesAsTheModelSaysIsNoGap) {
    sim::LinkParams link;
    link.to_host.packet_loss = {sim::LossUnit::frame, 0.005, 0.25, 0.0, 1.0};
    int flagged = 0;
    for (std::uint64_t seed : {7, 8, 9}) {
        const LogData log = log_of(simulate_slots(frame_loss_of(link, false), 5000, seed));
        flagged += !diagnose_link(log, link, BatteryOptions{}, 40, seed, 0.05, true).located.empty();
    }
    EXPECT_LE(flagged, 1);
}

// A polled log whose polls go unanswered: its rows step on in time but not in sequence number, which only a link that
// loses requests makes.
TEST(LinkLoss, UnansweredPollsAreLocatedAsRowSpacing) {
    LogData log = log_of(std::vector<std::uint8_t>(2000, 0));
    for (std::size_t k = 0; k < log.t_s.size(); ++k)
        log.t_s[k] += static_cast<double>(k / 100);  // a poll missed per 100
    log.metadata.set("mode", std::string("poll"));
    const LinkFindings f = diagnose_link(log, lossless(), BatteryOptions{}, 40, 5, 0.05, true);
    ASSERT_FALSE(f.located.empty());
    EXPECT_EQ(f.layout[f.located.front().index].statistic, "spacing");
    sim::LinkParams requests;
    requests.to_firmware.byte_error_rate = 1.0 - std::pow(0.99, 1.0 / 9.0);  // a 9-byte POLL lost 1 % of the time
    EXPECT_NEAR(frame_loss_of(requests, true).unanswered, 0.01, 1e-9);
}

}  // namespace
}  // namespace driftlab::host::gap
