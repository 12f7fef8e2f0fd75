// Fig. 2 of the paper from a host-in-the-loop log: least-squares smoothing on the firmware takes the gyro's raw
// standard deviation 0.187 deg/s down to 0.045 deg/s. Expectations are the paper's published numbers and the
// closed form sigma/sqrt(N) of a mean of N white samples.
#include <gtest/gtest.h>

#include "tests/sim/hil/hil_test_support.hpp"

namespace driftlab::sim {
namespace {

using testing::preset;
using testing::run_into_memory;
using testing::stddev;

constexpr double kDpsPerCount = 90.0 / 512.0;
constexpr double kGPerCount = 1.0 / 512.0;

struct Columns {
    std::vector<double> raw, smoothed;
};

Columns columns(const std::vector<HilRecord>& rows, Channel c) {
    Columns out;
    for (const auto& r : rows) {
        EXPECT_TRUE(r.has_raw);
        // Only full windows: the first outputs after CONFIG_SET average fewer conversions.
        if (r.n_window < kFig2Window) continue;
        out.raw.push_back(r.raw_counts[channel_index(c)]);
        out.smoothed.push_back(r.value_counts[channel_index(c)]);
    }
    return out;
}

TEST(Fig2Preset, ProducesAThousandRawAndSmoothedRowsATenthOfASecondApart) {
    const auto run = run_into_memory(preset(Preset::fig2));
    ASSERT_EQ(run.rows.size(), 1000u);
    for (std::size_t i = 1; i < run.rows.size(); ++i)
        EXPECT_NEAR(run.rows[i].t_s - run.rows[i - 1].t_s, 0.1, 0.0011) << i;  // polls land on the 1 ms grid
    EXPECT_EQ(run.summary.host.frames_lost, 0u);
}

TEST(Fig2Preset, GyroStdFallsFromThePapersRawToItsSmoothedValue) {
    const auto run = run_into_memory(preset(Preset::fig2));
    const Columns g = columns(run.rows, Channel::gyro);
    ASSERT_GE(g.raw.size(), 990u);
    const double raw_dps = stddev(g.raw) * kDpsPerCount;
    const double smoothed_dps = stddev(g.smoothed) * kDpsPerCount;
    // 1000 outputs: a sample std has a relative standard error of 1/sqrt(2·1000) = 2.2 %; 4 of it (9 %). The raw std is
    // the model's input (the paper's 0.187 deg/s), the smoothed one the closed form raw / sqrt(window) (17 conversions:
    // 0.0454 deg/s, the paper's 0.045 within the same bound).
    EXPECT_NEAR(raw_dps, 0.187, 0.09 * 0.187);
    EXPECT_NEAR(stddev(g.smoothed) / (stddev(g.raw) / std::sqrt(double(kFig2Window))), 1.0, 0.09);
    EXPECT_NEAR(smoothed_dps, 0.045, 0.09 * 0.045);
}

TEST(Fig2Preset, AccelXSmoothedStdIsRawOverSqrtOfTheWindow) {
    // The paper's accel X went from 0.0141 to 0.0024 g, a factor sqrt(34.5): no single window reproduces both
    // channels' reductions, and the fig2 preset matches the gyro's. Here the closed form is the expectation.
    const auto run = run_into_memory(preset(Preset::fig2));
    const Columns a = columns(run.rows, Channel::accel_x);
    const double raw_g = stddev(a.raw) * kGPerCount;
    EXPECT_NEAR(raw_g, 0.0141, 0.1 * 0.0141);
    // 1000 outputs: the sample std has a relative standard error of 1/sqrt(2·1000) = 2.2 %.
    EXPECT_NEAR(stddev(a.smoothed) / (stddev(a.raw) / std::sqrt(double(kFig2Window))), 1.0, 0.09);
}

}  // namespace
}  // namespace driftlab::sim
