// TickUnwrapper and ticks_run_on: the 32-bit firmware tick made 64-bit, and whether a STATUS after a link gap shows
// a firmware that ran on (its uptime is where the host's clock says the old count has got to, wraps included).
#include "driftlab/receiver/tick_unwrapper.hpp"

#include <gtest/gtest.h>

#include <cmath>

using driftlab::receiver::ticks_run_on;
using driftlab::receiver::TickUnwrapper;

namespace {
constexpr std::uint64_t kWrap = std::uint64_t{1} << 32;
}

TEST(TickUnwrapper, CountsOnAcrossTheWrapAndTakesAShortStepBackAsAStepBack) {
    TickUnwrapper u;
    EXPECT_EQ(u.unwrap(0xFFFFFF00u), 0xFFFFFF00u);
    EXPECT_EQ(u.unwrap(0x00000010u), kWrap + 0x10);
    EXPECT_EQ(u.unwrap(0x00000008u), kWrap + 0x08);  // a repeated, older answer: not another wrap
}

TEST(TickUnwrapper, AnExpectationPlacesTheNextTickWrapsAwayOnlyOnce) {
    TickUnwrapper u;
    u.unwrap(1000);
    // Three wraps and 2^31 + 5000 ticks later (more than the nearest-after rule can span).
    const std::uint64_t truth = 1000 + 3 * kWrap + (kWrap / 2) + 5000;
    u.expect_near(truth - 40000);  // the host's estimate, 40000 ticks short
    EXPECT_EQ(u.unwrap(static_cast<std::uint32_t>(truth)), truth);
    EXPECT_EQ(u.unwrap(static_cast<std::uint32_t>(truth + 25000)), truth + 25000);  // then nearest after again
}

TEST(TicksRunOn, IsTheForwardDistanceWithTheWrapsTheHostsClockImplies) {
    // Without a wrap, across one, and across two: the exact distance whatever the host's error within tolerance.
    EXPECT_EQ(ticks_run_on(100, 1600, 1400.0, 500.0), std::optional<std::uint64_t>(1500));
    EXPECT_EQ(ticks_run_on(0xFFFFF000u, 0x1000u, 0x2000 + 300.0, 500.0), std::optional<std::uint64_t>(0x2000));
    const std::uint64_t two_wraps = 2 * kWrap + 0x2000;
    EXPECT_EQ(ticks_run_on(0xFFFFF000u, 0x1000u, static_cast<double>(two_wraps) * 1.004, 0.01 * two_wraps),
              std::optional<std::uint64_t>(two_wraps));
}

TEST(TicksRunOn, IsEmptyWhereTheUptimeIsNotWhereTheCountWouldBe) {
    // A firmware restarted 1 s (250000 ticks) before it answered, after a gap of 6 s that crossed the old count's wrap.
    const std::uint32_t last = static_cast<std::uint32_t>(kWrap - 275000);
    EXPECT_FALSE(ticks_run_on(last, 250000, 1.5e6, 65000.0));
    // The same uptime with the count run on: 275000 + 250000 ticks.
    EXPECT_EQ(ticks_run_on(last, 250000, 525000.0 + 60000.0, 65000.0), std::optional<std::uint64_t>(525000));
    EXPECT_FALSE(ticks_run_on(last, 250000, std::nan(""), 65000.0));
}
