// Stream mode on a lossless link: one row per output period, each with its RAW, the last one included (its RAW is
// still on the line when the run's time is up, and is awaited until the firmware acknowledges the stop).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "tests/sim/hil/hil_test_support.hpp"

namespace driftlab::sim {
namespace {

using testing::run_into_memory;

HilOptions streamed(double period_s, double duration_s, bool raw) {
    HilOptions o;
    o.model = paper_model();
    o.model.firmware.output_period_ms = static_cast<std::uint16_t>(period_s * 1000.0);
    o.model.firmware.mode = static_cast<std::uint8_t>(proto::OutputMode::stream);
    o.model.firmware.raw = raw ? 1 : 0;
    o.duration_s = duration_s;
    return o;
}

TEST(StreamMode, EveryOutputOfALosslessRunIsARowWithItsRawCodes) {
    for (const double period_s : {1.0, 0.5}) {
        const testing::Run r = run_into_memory(streamed(period_s, 10.0, true));
        const auto outputs = static_cast<std::size_t>(10.0 / period_s);
        EXPECT_EQ(r.summary.host.frames_lost, 0u) << period_s;
        EXPECT_EQ(r.summary.host.rows_missing_raw, 0u) << period_s;
        ASSERT_EQ(r.rows.size(), outputs) << period_s;
        for (const HilRecord& row : r.rows) EXPECT_TRUE(row.has_raw) << row.t_s;
        EXPECT_NEAR(r.rows.back().t_s - r.rows.front().t_s, (static_cast<double>(outputs) - 1.0) * period_s, 1e-3);
    }
}

// Progress rises and reports the end once: a stream run awaiting its last RAW past the duration had reported 1.0
// inside the loop too, and the terminal's bar printed its 100 % line twice.
TEST(StreamMode, ProgressReportsTheEndOnce) {
    HilOptions o = streamed(0.5, 10.0, true);
    std::vector<double> reports;
    o.progress = [&reports](double f) { reports.push_back(f); };
    run_into_memory(o);
    ASSERT_GE(reports.size(), 2u);
    EXPECT_EQ(std::count(reports.begin(), reports.end(), 1.0), 1);
    EXPECT_EQ(reports.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(reports.begin(), reports.end()));
}

TEST(StreamMode, RawModeKeepsAsManyRowsAsSmoothedOnly) {
    const testing::Run plain = run_into_memory(streamed(1.0, 10.0, false));
    const testing::Run raw = run_into_memory(streamed(1.0, 10.0, true));
    EXPECT_EQ(raw.rows.size(), plain.rows.size());
}

// The paper's 9600-baud link carries 960 bytes/s: a SAMPLE frame (38 bytes) every 40 ms fits (950 bytes/s), and the
// run logs every output; every 39 ms does not (974); with RAW (59 bytes) 62 ms fits and 61 ms does not. Beyond it
// outputs would queue without end and the run's time would end before most arrived: link_capacity_refusal says so,
// with the figures, and `driftlab hil` refuses the run (its test: HilCli.AnOutputRateTheLinkCannotCarry...).
TEST(StreamMode, AnOutputRateBeyondTheLinkIsRefused) {
    const auto options = [](double period_s, bool raw) {
        HilOptions o = streamed(period_s, 2.0, raw);
        o.model.firmware.conversions_per_output = 8;
        return o;
    };
    EXPECT_FALSE(link_capacity_refusal(options(0.040, false).model));
    EXPECT_GE(run_into_memory(options(0.040, false)).rows.size(), 49u);  // 50 outputs in 2 s
    EXPECT_TRUE(link_capacity_refusal(options(0.039, false).model));
    EXPECT_FALSE(link_capacity_refusal(options(0.062, true).model));
    EXPECT_GE(run_into_memory(options(0.062, true)).rows.size(), 31u);  // 32 outputs
    const auto refusal = link_capacity_refusal(options(0.061, true).model);
    ASSERT_TRUE(refusal);
    EXPECT_NE(refusal->find("cannot carry 59 bytes (SAMPLE + RAW) every 61 ms"), std::string::npos) << *refusal;
}

}  // namespace
}  // namespace driftlab::sim
