// The two held-out designs: forecast (first fit_fraction by time) and interleaved (tenths 0, 4, 5, 7, 9), and the
// battery's cells following them.
#include <gtest/gtest.h>

#include "host/gap/statistics.hpp"

namespace driftlab::host::gap {
namespace {

std::vector<double> instants(std::size_t n) {
    std::vector<double> t(n);
    for (std::size_t k = 0; k < n; ++k) t[k] = static_cast<double>(k + 1);
    return t;
}

TEST(Holdout, ForecastFitsTheFirstPartByTime) {
    BatteryOptions o;
    o.holdout = Holdout::forecast;
    o.fit_fraction = 0.6;
    const auto mask = fitting_mask(instants(1001), o);
    // t = 1 .. 1001: the split is at 1 + 0.6 * 1000 = 601.
    for (std::size_t k = 0; k < mask.size(); ++k) EXPECT_EQ(mask[k], k + 1 <= 601) << k;
}

bool fitting_tenth(std::size_t tenth) { return tenth == 0 || tenth == 4 || tenth == 5 || tenth == 7 || tenth == 9; }

TEST(Holdout, InterleavedTakesFiveAperiodicTenthsAndIsTheDefault) {
    BatteryOptions o;
    EXPECT_EQ(o.holdout, Holdout::interleaved);
    const auto mask = fitting_mask(instants(1000), o);
    for (std::size_t k = 0; k < mask.size(); ++k) EXPECT_EQ(mask[k], fitting_tenth(k / 100)) << k;
}

TEST(Holdout, WindowedCellsFollowTheDesign) {
    BatteryOptions o;
    o.channels = {true, false, false, false};
    o.holdout = Holdout::interleaved;
    const auto t = instants(1000);
    std::vector<double> y(t.size());
    for (std::size_t k = 0; k < y.size(); ++k) y[k] = 500.0 + 0.25 * static_cast<double>((k * 7919) % 13);
    std::array<const std::vector<double>*, kChannelCount> ys{&y, nullptr, nullptr, nullptr};
    std::vector<Cell> layout;
    compute_battery(t, ys, o, &layout);
    int window = 0;
    for (const auto& c : layout) {
        if (c.statistic != "mean") continue;
        EXPECT_EQ(c.segment, fitting_tenth(static_cast<std::size_t>(window)) ? Segment::fit : Segment::heldout)
            << c.cell;
        ++window;
    }
    EXPECT_EQ(window, 10);
    EXPECT_EQ(holdout_from_name("interleaved"), Holdout::interleaved);
    EXPECT_EQ(holdout_from_name("forecast"), Holdout::forecast);
    EXPECT_FALSE(holdout_from_name("random").has_value());
}

}  // namespace
}  // namespace driftlab::host::gap
