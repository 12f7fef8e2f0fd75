// Progress-line durations: the units a person reads, and the pace-so-far extrapolation.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "host/util/time_left.hpp"

namespace driftlab::host {
namespace {

TEST(SecondsSince, AStartTwoSecondsAgoIsTwoSecondsAgo) {
    const double s = seconds_since(std::chrono::steady_clock::now() - std::chrono::seconds(2));
    EXPECT_GE(s, 2.0);
    EXPECT_LT(s, 60.0);  // however loaded the machine
}

TEST(FormatDuration, SecondsMinutesAndHoursRoundToTheLastUnitShown) {
    EXPECT_EQ(format_duration(0.0), "0 s");
    EXPECT_EQ(format_duration(44.6), "45 s");
    EXPECT_EQ(format_duration(59.4), "59 s");
    EXPECT_EQ(format_duration(59.6), "1 min 00 s");
    EXPECT_EQ(format_duration(125.0), "2 min 05 s");
    EXPECT_EQ(format_duration(3599.4), "59 min 59 s");
    EXPECT_EQ(format_duration(3900.0), "1 h 05 min");
    EXPECT_EQ(format_duration(3600.0 * 25 + 29.0), "25 h 00 min");
    EXPECT_EQ(format_duration(-3.0), "0 s");
}

// Remaining = elapsed x (1 - f) / f: a quarter done in 30 s leaves 90 s.
TEST(TimeLeft, TheRestTakesThePaceSoFar) {
    EXPECT_EQ(time_left(0.25, 30.0), "about 1 min 30 s left");
    EXPECT_EQ(time_left(0.5, 600.0), "about 10 min 00 s left");
    EXPECT_EQ(time_left(0.1, 400.0), "about 1 h 00 min left");
}

TEST(TimeLeft, NothingIsGuessedBeforeThePaceIsKnownOrOnceDone) {
    EXPECT_EQ(time_left(0.5, 0.5), "");     // under a second: start-up dominates
    EXPECT_EQ(time_left(0.005, 10.0), "");  // under 1 % done
    EXPECT_EQ(time_left(1.0, 10.0), "");
    EXPECT_EQ(time_left(0.99, 10.0), "");  // 0.1 s left: "about 0 s" says nothing
    EXPECT_EQ(time_left(std::nan(""), 10.0), "");
}

}  // namespace
}  // namespace driftlab::host
