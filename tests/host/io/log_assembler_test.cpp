// LogAssembler across a reconnect, fed as the recorder feeds it: an output the streaming board sends while the
// recorder repeats its handshake is a row after the `# gap:` line, wherever it falls among the handshake's replies;
// and a STATUS uptime below the last tick marks a firmware restart after that line, unless the host's clock says the
// board's count ran on to it across the wrap of its 32-bit tick.
#include "host/io/log_assembler.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>
#include <string>

#include "driftlab/proto/encoder.hpp"
#include "host/io/status_line.hpp"
#include "host/log/log_reader.hpp"
#include "tests/host/io/assembler_board.hpp"

namespace fs = std::filesystem;
using namespace driftlab;
using namespace driftlab::host;
using namespace driftlab::host::io;
using namespace driftlab::host::io::test_board;

namespace {

// Three rows, then the link is lost for 6 s while the board streams on (60 outputs never received).
void record_until_unplugged(Board& b) {
    b.version();
    b.config();
    b.event("start");
    for (std::uint32_t k = 1; k <= 3; ++k) b.sample(k * kTicksPerOutput);
    b.event("lost");
    b.skip(60);
    b.wait_us(6'000'000);
}

// The recorder's handshake after reconnecting (VERSION, CONFIG_SET, CONFIG, STATUS), one streamed output at
// `tick` arriving between the replies, the gap line, then the next output.
void reconnect_with_an_output_inside(Board& b, std::uint32_t tick, std::uint32_t uptime, bool answer_status = true) {
    b.version();
    b.ack();
    b.sample(tick);
    b.config();
    if (answer_status) b.status(uptime);
    b.event("gap: link lost after t_s=0.3, reconnected after 6 s, 1 attempts");
    b.event("resumed");
    b.sample(tick + kTicksPerOutput);
}

// Three rows, the loss, the reconnect with an output at `tick` inside the handshake: the log as read back.
LogData recorded_across_a_reconnect(const std::string& name, std::uint32_t tick) {
    const std::string path = temp_log(name);
    {
        LogAssembler a(path, {{"port", "/dev/pts/9"}, {"capture", name + ".cap"}});
        Board b(a);
        record_until_unplugged(b);
        reconnect_with_an_output_inside(b, tick, tick + 100);
        a.finish();
    }
    LogData log = read_log(path);
    fs::remove(path);
    return log;
}

// A board whose clock runs `speed` times the host's (a simulated board's --speed; 1.0 for a real one) streams `rows`
// outputs from tick `first`, is unplugged for `gap_s` of host time while streaming on, and is found after the
// reconnect with its count run on (or restarted, when `uptime_after` is set to the restarted firmware's uptime).
struct Unplugged {
    double speed = 1.0;
    std::uint32_t first = kTicksPerOutput;
    std::uint32_t rows = 3;
    double gap_s = 6.0;
    std::optional<std::uint32_t> uptime_after;
    bool answer_status = true;     ///< false: the STATUS request went unanswered (a lossy radio link)
    std::uint32_t rows_after = 1;  ///< outputs after the handshake's
};

LogData recorded_across_an_unplug(const std::string& name, const Unplugged& u, AssemblyStats& stats) {
    const std::string path = temp_log(name);
    const auto output_us = static_cast<std::uint64_t>(100000 / u.speed);
    {
        LogAssembler a(path, {{"port", "/dev/pts/9"}, {"capture", name + ".cap"}});
        Board b(a);
        b.version();
        b.config();
        b.event("start");
        std::uint32_t tick = u.first;
        for (std::uint32_t k = 0; k < u.rows; ++k, tick += kTicksPerOutput) {
            b.wait_us(output_us - 1000);  // sample() adds the frame's own 1 ms
            b.sample(tick);
        }
        tick -= kTicksPerOutput;  // the newest row's
        b.event("lost");
        const double gap_ticks = u.gap_s * u.speed * kTickHz;
        b.skip(static_cast<std::uint64_t>(gap_ticks / kTicksPerOutput));
        b.wait_us(static_cast<std::uint64_t>(u.gap_s * 1e6));
        // The handshake's replies arrive 1 ms apart; the output inside it is the first one after the gap.
        const auto ran_on = static_cast<std::uint32_t>(tick + static_cast<std::uint64_t>(gap_ticks));
        const std::uint32_t next = u.uptime_after ? *u.uptime_after : ran_on + kTicksPerOutput;
        b.version();
        b.ack();
        b.sample(next);
        b.config();
        if (u.answer_status) b.status(next + 100);
        b.event("gap: link lost, reconnected");
        b.event("resumed");
        for (std::uint32_t k = 1; k <= u.rows_after; ++k) {
            b.wait_us(output_us - 1000);
            b.sample(next + k * kTicksPerOutput);
        }
        a.finish();
        stats = a.stats();
    }
    LogData log = read_log(path);
    fs::remove(path);
    return log;
}

}  // namespace

TEST(LogAssembler, AnOutputStreamedDuringTheReconnectHandshakeIsARowAfterTheGap) {
    const LogData log = recorded_across_a_reconnect("handshake.csv", 64 * kTicksPerOutput);
    ASSERT_EQ(log.size(), 5u);
    ASSERT_EQ(log.gaps.size(), 1u);
    EXPECT_EQ(log.gaps[0].before_row, 3u);  // the handshake's output follows the gap line
    EXPECT_DOUBLE_EQ(log.t_s[2], 0.3);
    EXPECT_DOUBLE_EQ(log.t_s[3], 6.4);
    EXPECT_DOUBLE_EQ(log.t_s[4], 6.5);
    EXPECT_EQ(log.seq[3] - log.seq[2], 63u);  // 60 unseen frames, VERSION and ACK between the rows
}

TEST(LogAssembler, AFirmwareRestartDuringTheGapIsMarkedAfterTheLinkLoss) {
    // A fresh firmware counts its ticks from 0 again.
    const LogData log = recorded_across_a_reconnect("restart.csv", 2 * kTicksPerOutput);
    ASSERT_EQ(log.size(), 5u);
    ASSERT_EQ(log.gaps.size(), 2u);
    EXPECT_NE(log.gaps[0].text.find("link lost"), std::string::npos) << log.gaps[0].text;
    EXPECT_NE(log.gaps[1].text.find("firmware restarted"), std::string::npos) << log.gaps[1].text;
    EXPECT_EQ(log.gaps[1].before_row, 3u);
    // tick and seq continue after the last row instead of restarting
    EXPECT_GT(log.t_s[3], log.t_s[2]);
    EXPECT_GT(log.seq[3], log.seq[2]);
    EXPECT_GT(log.t_s[4], log.t_s[3]);
}

TEST(LogAssembler, ACountRunOnAcrossTheTickWrapIsNoFirmwareRestart) {
    // A simulated board at 4x the host's clock, its 32-bit tick 20 s short of the wrap when unplugged for 6 s of
    // host time (24 s of its own): the STATUS uptime is below the last tick, but it is where the board's count,
    // at the rate measured over the rows, has got to; t_s runs on across the wrap.
    Unplugged u;
    u.speed = 4.0;
    u.rows = 600;
    u.first = static_cast<std::uint32_t>((std::uint64_t{1} << 32) - 20 * kTickHz - 599 * kTicksPerOutput);
    AssemblyStats stats;
    const LogData log = recorded_across_an_unplug("runon.csv", u, stats);
    EXPECT_EQ(stats.firmware_restarts, 0u);
    ASSERT_EQ(log.gaps.size(), 1u);
    const std::size_t k = log.gaps[0].before_row;
    ASSERT_EQ(k, 600u);
    ASSERT_EQ(log.size(), 602u);
    EXPECT_NEAR(log.t_s[k] - log.t_s[k - 1], 24.1, 1e-9);  // the gap's 24 s of board time, and one output
    EXPECT_NEAR(log.t_s[k + 1] - log.t_s[k], 0.1, 1e-9);
    EXPECT_GT(log.t_s[k], 4294967296.0 / kTickHz);  // past the wrap, unwrapped
}

TEST(LogAssembler, AGapLongerThanHalfTheTickRangeKeepsTheRowsAfterIt) {
    // 3 h unplugged: the count runs on by more than 2^31 ticks, which the nearest-after rule alone would read as
    // a step back (and drop every later row as not after the previous one).
    Unplugged u;
    u.gap_s = 3 * 3600.0;
    AssemblyStats stats;
    const LogData log = recorded_across_an_unplug("long.csv", u, stats);
    EXPECT_EQ(stats.firmware_restarts, 0u);
    EXPECT_EQ(stats.stale_samples, 0u);
    ASSERT_EQ(log.size(), 5u);
    EXPECT_NEAR(log.t_s[3] - log.t_s[2], 3 * 3600.0 + 0.1, 1e-9);
    // Streamed on meanwhile: 108000 outputs never received, then VERSION and ACK before the row.
    EXPECT_EQ(log.seq[3] - log.seq[2], 108000u + 3u);
}

TEST(LogAssembler, AFirmwareRestartedWhereTheOldCountWouldHaveWrappedIsARestart) {
    // The old count would have crossed its wrap during the 6 s gap, but the uptime (1 s since a reboot) is not
    // where it would have got to.
    Unplugged u;
    u.first = static_cast<std::uint32_t>((std::uint64_t{1} << 32) - 2 * kTickHz);
    u.uptime_after = kTickHz;
    AssemblyStats stats;
    const LogData log = recorded_across_an_unplug("rebooted.csv", u, stats);
    EXPECT_EQ(stats.firmware_restarts, 1u);
    ASSERT_EQ(log.gaps.size(), 2u);
    EXPECT_NE(log.gaps[1].text.find("firmware restarted"), std::string::npos) << log.gaps[1].text;
    // 1 s since the reboot when the STATUS left, 0.4 ms into the handshake: the shortest text, not "1.000400".
    EXPECT_NE(log.gaps[1].text.find("(uptime 1.0004 s)"), std::string::npos) << log.gaps[1].text;
    ASSERT_EQ(log.size(), 5u);
    EXPECT_GT(log.t_s[3], log.t_s[2]);
}

// Without a STATUS (its request went unanswered), the first SAMPLE after the gap tells: a restarted firmware's rows
// are kept and the restart marked (they had been dropped as duplicates), and a count run on for 3 h is placed
// there (its rows had been dropped as not after the previous one).
TEST(LogAssembler, WithoutAStatusTheFirstSampleAfterTheGapDecides) {
    Unplugged restarted;
    restarted.answer_status = false;
    restarted.rows = 600;
    restarted.gap_s = 60.0;
    restarted.uptime_after = 5 * kTickHz;
    restarted.rows_after = 50;
    AssemblyStats stats;
    const LogData log = recorded_across_an_unplug("nostatus_restart.csv", restarted, stats);
    EXPECT_EQ(stats.firmware_restarts, 1u);
    EXPECT_EQ(log.size(), 651u);
    Unplugged ran_on;
    ran_on.answer_status = false;
    ran_on.gap_s = 3 * 3600.0;
    ran_on.rows_after = 50;
    const LogData long_gap = recorded_across_an_unplug("nostatus_long.csv", ran_on, stats);
    EXPECT_EQ(stats.firmware_restarts, 0u);
    ASSERT_EQ(long_gap.size(), 54u);
    EXPECT_NEAR(long_gap.t_s[3] - long_gap.t_s[2], 3 * 3600.0 + 0.1, 1e-9);
}

// A firmware that restarted early in a long gap has an uptime above the last row's tick but far short of where a
// run-on would be: a restart (its rows had been dropped as duplicates, none marked).
TEST(LogAssembler, AnUptimeShortOfTheRunOnIsARestartEvenAboveTheLastTick) {
    Unplugged u;
    u.rows = 6000;                   // 600 s from power-on
    u.gap_s = 1200.0;                // a run-on would be at 1800 s
    u.uptime_after = 900 * kTickHz;  // rebooted 300 s into the gap
    u.rows_after = 100;
    AssemblyStats stats;
    const LogData log = recorded_across_an_unplug("early_restart.csv", u, stats);
    EXPECT_EQ(stats.firmware_restarts, 1u);
    EXPECT_EQ(log.size(), 6101u);
}

TEST(LogAssembler, ASampleBeyondTheConvertersReachIsSkippedAndCounted) {
    // A frame whose CRC holds can still carry a value no 10-bit estimate reaches (a firmware fault): the rows around
    // it are kept, it is counted, and the log reads back.
    AssemblyStats stats;
    const LogData log = recorded(
        "reach.csv", 0,
        [](Board& b) {
            b.sample(1 * kTicksPerOutput);
            b.sample(2 * kTicksPerOutput, 1366 * 256);  // beyond 4/3 of full scale
            b.sample(3 * kTicksPerOutput, -341 * 256);  // within: an order-1 estimate's undershoot
        },
        stats);
    EXPECT_EQ(stats.unreachable_samples, 1u);
    EXPECT_EQ(stats.rows, 2u);
    ASSERT_EQ(log.size(), 2u);
    EXPECT_DOUBLE_EQ(log.t_s[1], 0.3);
    EXPECT_EQ(log.channel(Channel::gyro)[1], -341.0);
}

TEST(LogAssembler, ASampleOfAnEmptyWindowIsSkippedAndCounted) {
    // A POLL answered just after a CONFIG restarted the windows holds no conversion: every value 0, inside the
    // converter's range, so only n_window tells it from a reading (it had put a row of zeros first in a log).
    AssemblyStats stats;
    const LogData log = recorded(
        "empty.csv", 0,
        [](Board& b) {
            b.sample(1 * kTicksPerOutput, 0, 0);
            b.sample(2 * kTicksPerOutput, 500 * 256, 1);  // one conversion: a reading
            b.sample(3 * kTicksPerOutput);
        },
        stats);
    EXPECT_EQ(stats.empty_samples, 1u);
    EXPECT_EQ(stats.rows, 2u);
    ASSERT_EQ(log.size(), 2u);
    EXPECT_DOUBLE_EQ(log.t_s[0], 0.2);
    EXPECT_EQ(skipped_samples(stats),
              "skipped 1 sample: 0 repeated (time not after the previous row), 0 beyond the converter's reach, "
              "1 of an empty window (just after a CONFIG restarted the windows)");
}

TEST(LogAssembler, ARawFrameWithACodeTheConverterCannotMakeIsKeptOutLikeALostOne) {
    AssemblyStats stats;
    const LogData log = recorded(
        "rawreach.csv", 1,
        [](Board& b) {
            b.sample(1 * kTicksPerOutput);
            b.raw(1 * kTicksPerOutput, 1023);  // the 10-bit converter's top code
            b.sample(2 * kTicksPerOutput);
            b.raw(2 * kTicksPerOutput, 1024);  // no 10-bit code
            b.sample(3 * kTicksPerOutput);
        },
        stats);
    ASSERT_EQ(log.size(), 3u);
    EXPECT_EQ(log.optional_columns.at("raw_gyro"), (std::vector<double>{1023.0, -1.0, -1.0}));
    EXPECT_EQ(log.optional_columns.at("flags"), (std::vector<double>{0.0, kFlagRawMissing, kFlagRawMissing}));
    EXPECT_EQ(stats.raw_missing, 2u);  // the unmakeable code and the last row's RAW that never came
}

// A CONFIG turning raw on that arrives mid-recording (a stray or forged frame) changes neither how rows are read nor
// which columns they fill: it had ended `record` with "log row has 9 optional values, header has 4".
TEST(LogAssembler, AConfigArrivingMidRecordingChangesNoRow) {
    AssemblyStats stats;
    const LogData log = recorded(
        "midconfig.csv", 0,
        [](Board& b) {
            b.sample(1 * kTicksPerOutput);
            b.config(1);
            b.sample(2 * kTicksPerOutput);
            b.raw(2 * kTicksPerOutput, 501);
            b.sample(3 * kTicksPerOutput);
        },
        stats);
    ASSERT_EQ(log.size(), 3u);
    EXPECT_EQ(log.optional_columns.count("raw_gyro"), 0u);
    EXPECT_EQ(stats.raw_missing, 0u);
}
