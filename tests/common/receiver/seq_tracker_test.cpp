// SeqTracker: unwrapping across the 16-bit wrap and exact lost/late/duplicate accounting.
#include "driftlab/receiver/seq_tracker.hpp"

#include <gtest/gtest.h>

using namespace driftlab::receiver;

TEST(SeqTracker, UnwrapsAcrossTheWrapWithoutCountingLosses) {
    SeqTracker t;
    std::uint64_t last = 0;
    for (std::uint32_t n = 65530; n < 65530 + 20; ++n) last = t.accept(static_cast<std::uint16_t>(n)).unwrapped;
    EXPECT_EQ(last, 65530u + 19u);
    EXPECT_EQ(t.lost(), 0u);
    EXPECT_EQ(t.received(), 20u);
}

TEST(SeqTracker, AJumpCountsEveryMissingNumber) {
    SeqTracker t;
    static_cast<void>(t.accept(10));
    static_cast<void>(t.accept(11));
    const SeqResult r = t.accept(20);
    EXPECT_EQ(r.verdict, SeqVerdict::fresh);
    EXPECT_EQ(t.lost(), 8u);  // 12..19
}

TEST(SeqTracker, ALateFrameMovesFromLostToReorderedAndARepeatIsADuplicate) {
    SeqTracker t;
    for (std::uint16_t s : {1, 2, 4, 5}) static_cast<void>(t.accept(s));
    EXPECT_EQ(t.lost(), 1u);
    EXPECT_EQ(t.accept(3).verdict, SeqVerdict::late);
    EXPECT_EQ(t.lost(), 0u);
    EXPECT_EQ(t.reordered(), 1u);
    EXPECT_EQ(t.accept(4).verdict, SeqVerdict::duplicate);
    EXPECT_EQ(t.accept(3).verdict, SeqVerdict::duplicate);
    EXPECT_EQ(t.duplicates(), 2u);
    // sent = received - duplicates + lost
    EXPECT_EQ(t.received() - t.duplicates() + t.lost(), 5u);
}

TEST(SeqTracker, AfterALongGapTheHintChoosesTheRightWrap) {
    SeqTracker t;
    static_cast<void>(t.accept(100));
    // 70000 frames later (more than half the 16-bit range): nearest-to-newest would guess wrong.
    const std::uint64_t truth = 100 + 70000;
    t.expect_near(truth - 50);
    EXPECT_EQ(t.accept(static_cast<std::uint16_t>(truth)).unwrapped, truth);
    EXPECT_EQ(t.lost(), 69999u);
}

TEST(SeqTracker, ARestartedSenderContinuesAfterTheNewest) {
    SeqTracker t;
    for (std::uint16_t s = 500; s < 510; ++s) static_cast<void>(t.accept(s));
    t.restart_epoch();
    EXPECT_EQ(t.accept(0).unwrapped, 510u);
    EXPECT_EQ(t.accept(1).unwrapped, 511u);
    EXPECT_EQ(t.lost(), 0u);
}

TEST(UnwrapNear, NeverGoesBelowZero) {
    EXPECT_EQ(unwrap_near(65535, 0), 65535u);
    EXPECT_EQ(unwrap_near(5, 65540), 65541u);
    EXPECT_EQ(unwrap_near(65535, 65536), 65535u);
}
