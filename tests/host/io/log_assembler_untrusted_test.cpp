// The link is untrusted (docs/security.md): LogAssembler fed frames another transmitter forged among the board's, a
// VERSION or CONFIG that differs from the handshake's, a SAMPLE with a seq the board's own output also carries, an ACK
// of a CONFIG_SET the recording never sent.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "host/io/log_assembler.hpp"
#include "host/io/status_line.hpp"
#include "host/log/log_reader.hpp"
#include "tests/host/io/assembler_board.hpp"

using namespace driftlab;
using namespace driftlab::host;
using namespace driftlab::host::io;
using namespace driftlab::host::io::test_board;

// The link is untrusted (docs/security.md): a VERSION or CONFIG after the start that differs from the handshake's is
// counted, noted among the rows and ignored, so that rows keep their time base and columns.
TEST(LogAssembler, AVersionOrConfigDifferingFromTheHandshakesIsNotedAndIgnored) {
    const std::string path = temp_log("unexpected.csv");
    AssemblyStats stats;
    {
        LogAssembler a(path, {{"port", "/dev/pts/9"}, {"capture", "unexpected.cap"}});
        Board b(a);
        b.version();
        b.config();
        b.event("start");
        b.sample(1 * kTicksPerOutput);
        b.version(0);  // a tick rate of 0 had made t_s infinite
        b.sample(2 * kTicksPerOutput);
        b.config(1, 4);  // raw on, another window
        b.sample(3 * kTicksPerOutput);
        b.version();  // the handshake's own: nothing to note
        b.config();
        b.sample(4 * kTicksPerOutput);
        a.finish();
        stats = a.stats();
    }
    std::ifstream in(path);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("# unexpected: VERSION tick_hz 250000 -> 0 (frame seq 3) ignored"), std::string::npos) << text;
    EXPECT_NE(text.find("# unexpected: CONFIG window 8 -> 4, raw 0 -> 1 (frame seq 5) ignored"), std::string::npos)
        << text;
    const LogData log = read_log(path);
    std::filesystem::remove(path);
    ASSERT_EQ(log.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(log.t_s[i], 0.1 * static_cast<double>(i + 1));
    EXPECT_EQ(stats.unexpected_versions, 1u);
    EXPECT_EQ(stats.unexpected_configs, 1u);
    EXPECT_EQ(
        untrusted_frames(stats),
        "untrusted frames: 1 VERSION and 1 CONFIG differing from the handshake's ignored (each noted in the log)");
}

// A forged SAMPLE with the next seq, before or after the real one: the two frames share a seq with different content,
// and neither becomes a row; a frame repeated as it was is a duplicate, no conflict.
TEST(LogAssembler, TwoFramesOfOneSeqWithDifferentContentKeepEachOtherOutOfTheLog) {
    AssemblyStats stats;
    const LogData log = recorded(
        "conflict.csv", 0,
        [](Board& b) {
            b.sample(1 * kTicksPerOutput);
            b.sample(2 * kTicksPerOutput, 900 * 256);  // forged, with the seq the real output will carry
            b.rewind(1);
            b.sample(2 * kTicksPerOutput);  // the real one
            b.sample(3 * kTicksPerOutput);
            b.rewind(1);
            b.sample(3 * kTicksPerOutput);  // a repeat of the same frame
            b.sample(4 * kTicksPerOutput);
        },
        stats);
    ASSERT_EQ(log.size(), 3u);
    EXPECT_DOUBLE_EQ(log.t_s[0], 0.1);
    EXPECT_DOUBLE_EQ(log.t_s[1], 0.3);
    EXPECT_DOUBLE_EQ(log.t_s[2], 0.4);
    for (std::size_t i = 0; i < log.size(); ++i) EXPECT_DOUBLE_EQ(log.channel(Channel::gyro)[i], 500.0);
    EXPECT_EQ(stats.conflicting_frames, 1u);
    EXPECT_EQ(stats.conflicting_rows, 1u);
    EXPECT_EQ(stats.duplicate_frames, 2u);  // the real frame of the conflict, and the repeat
    EXPECT_EQ(untrusted_frames(stats),
              "untrusted frames: 1 shared its seq with another of other content (neither used; 1 row kept out)");
}

// A forged VERSION or CONFIG that takes a seq the board's output also carries, before or after it: the one that changes
// the handshake's is the forged one (the board's own changes follow only a CONFIG_SET, whose ACK ends the rows), so the
// SAMPLE of that seq stays a row; a SAMPLE beside a CONFIG equal to the handshake's is the forged one, and stays out.
TEST(LogAssembler, AForgedConfigSharingASamplesSeqLosesToTheSample) {
    AssemblyStats stats;
    const LogData log = recorded(
        "forged_config_seq.csv", 0,
        [](Board& b) {
            b.sample(1 * kTicksPerOutput);
            b.config(1, 4);  // forged, with the seq the next output will carry
            b.rewind(1);
            b.sample(2 * kTicksPerOutput);  // the real output
            b.sample(3 * kTicksPerOutput);
            b.rewind(1);
            b.version(0);                              // forged, with the seq of the output just received
            b.sample(4 * kTicksPerOutput, 900 * 256);  // forged, with the seq the board's CONFIG will carry
            b.rewind(1);
            b.config();  // the board's own, as the handshake set it
            b.sample(5 * kTicksPerOutput);
        },
        stats);
    ASSERT_EQ(log.size(), 4u);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(log.t_s[i], 0.1 * static_cast<double>(i + 1));
    EXPECT_DOUBLE_EQ(log.t_s[3], 0.5);
    for (std::size_t i = 0; i < log.size(); ++i) EXPECT_DOUBLE_EQ(log.channel(Channel::gyro)[i], 500.0);
    EXPECT_EQ(stats.unexpected_configs, 1u);
    EXPECT_EQ(stats.unexpected_versions, 1u);
    EXPECT_EQ(stats.conflicting_frames, 3u);
    EXPECT_EQ(stats.conflicting_rows, 1u);
}

// An ACK of a CONFIG_SET the recording did not send: another transmitter reconfigured the board. No SAMPLE after it is
// a row (its outputs follow a configuration the log does not state), and the log says so; an ACK inside a reconnect's
// handshake is the recorder's own (AnOutputStreamedDuringTheReconnectHandshakeIsARowAfterTheGap).
TEST(LogAssembler, AConfigSetAcknowledgedThatTheRecordingDidNotSendEndsItsRows) {
    const std::string path = temp_log("foreign_ack.csv");
    AssemblyStats stats;
    {
        LogAssembler a(path, {{"port", "/dev/pts/9"}, {"capture", "foreign_ack.cap"}});
        Board b(a);
        b.version();
        b.config();
        b.event("start");
        b.sample(1 * kTicksPerOutput);
        b.sample(2 * kTicksPerOutput);
        b.ack();
        b.sample(3 * kTicksPerOutput);
        b.ack();
        a.finish();
        stats = a.stats();
    }
    std::ifstream in(path);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("# unexpected: ACK of a CONFIG_SET this recording did not send (frame seq 4)"),
              std::string::npos)
        << text;
    const LogData log = read_log(path);
    std::filesystem::remove(path);
    ASSERT_EQ(log.size(), 2u);
    EXPECT_DOUBLE_EQ(log.t_s[1], 0.2);
    EXPECT_EQ(stats.foreign_config_acks, 2u);
}

// A CONFIG_SET from someone else whose ACK was lost: the board's windows restart, and a SAMPLE whose n_window is not
// the handshake's once that had filled ends the rows, as the ACK would have. Before it fills, a window of more
// conversions than the handshake set is as telling.
TEST(LogAssembler, ASampleOfAnotherWindowEndsTheRowsWhenTheAckWasLost) {
    AssemblyStats stats;
    const LogData log = recorded(
        "other_window.csv", 0,
        [](Board& b) {
            b.sample(1 * kTicksPerOutput, 500 * 256, 4);  // filling: a row
            b.sample(2 * kTicksPerOutput);                // full (8)
            b.sample(3 * kTicksPerOutput);
            b.sample(4 * kTicksPerOutput, 500 * 256, 3);  // restarted windows: reconfigured
            b.sample(5 * kTicksPerOutput);
        },
        stats);
    ASSERT_EQ(log.size(), 3u);
    EXPECT_DOUBLE_EQ(log.t_s[2], 0.3);
    EXPECT_EQ(stats.other_window_samples, 1u);
    EXPECT_TRUE(stats.board_reconfigured());
    EXPECT_NE(untrusted_frames(stats).find("a SAMPLE of a window the recording did not set"), std::string::npos);

    AssemblyStats wider;
    const LogData early = recorded(
        "wider_window.csv", 0,
        [](Board& b) {
            b.sample(1 * kTicksPerOutput, 500 * 256, 4);
            b.sample(2 * kTicksPerOutput, 500 * 256, 9);  // more than the handshake's 8
        },
        wider);
    ASSERT_EQ(early.size(), 1u);
    EXPECT_EQ(wider.other_window_samples, 1u);
}

namespace driftlab::host::io::test_board {
namespace {

// A board compensating with calibration 7 at the handshake: its rows are kept, the metadata says so; a SAMPLE of
// another calibration state (a warm restart: settled) ends the rows, and so does the ACK of a CAL_SET the recording
// did not send.
TEST(LogAssembler, ASampleOfAnotherCalibrationOrAForeignCalSetAckEndsTheRows) {
    for (const bool by_ack : {false, true}) {
        const std::string path = temp_log(by_ack ? "cal_ack.csv" : "cal_sample.csv");
        AssemblyStats stats;
        {
            LogAssembler a(path, {{"port", "/dev/pts/9"}, {"capture", "cal.cap"}});
            Board b(a);
            b.calibration(proto::CalState::active, 7);
            b.version();
            b.config();
            b.event("start");
            b.sample(1 * kTicksPerOutput);
            b.sample(2 * kTicksPerOutput);
            b.sample(3 * kTicksPerOutput);
            if (by_ack) {
                b.ack(proto::MsgType::cal_set);
            } else {
                b.calibration(proto::CalState::settled, 7);
            }
            b.sample(4 * kTicksPerOutput);
            b.sample(5 * kTicksPerOutput);
            a.finish();
            stats = a.stats();
        }
        const LogData log = read_log(path);
        std::filesystem::remove(path);
        EXPECT_EQ(log.metadata.get("cal_state"), "active");
        EXPECT_EQ(log.metadata.get_int("cal_id"), 7);
        EXPECT_EQ(log.size(), 3u) << (by_ack ? "ack" : "sample");
        EXPECT_EQ(stats.other_calibration_samples, by_ack ? 0u : 1u);
        EXPECT_EQ(stats.foreign_config_acks, by_ack ? 1u : 0u);
        EXPECT_TRUE(stats.board_reconfigured());
    }
}

}  // namespace
}  // namespace driftlab::host::io::test_board
