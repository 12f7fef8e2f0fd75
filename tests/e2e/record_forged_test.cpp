// `driftlab record` while a second program on the line (tests/e2e/pty_relay) injects forged frames among the board's,
// as another transmitter on its radio channel could (docs/security.md). The recording either goes on with every real
// row and the event reported, or stops with its documented exit code, every row so far whole; never a wrong row.
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <vector>

#include "driftlab/proto/messages.hpp"
#include "host/io/key_file.hpp"
#include "host/log/log_reader.hpp"
#include "sim/hil/eeprom_image.hpp"
#include "tests/e2e/e2e_support.hpp"
#include "tests/e2e/pty_relay.hpp"

using namespace driftlab;
using namespace driftlab::e2e;

namespace {

constexpr int kSamplesBeforeForgery = 50;
constexpr std::uint32_t kTicksPerOutput = 25000;  // 0.1 s at the firmware's 250 kHz tick

struct ForgedRun {
    RunResult record;
    host::LogData truth;
    int injected = 0;
};

// Records 20 s of 0.1 s outputs from a board paced 4x the wall clock through a relay that, once the board has sent
// kSamplesBeforeForgery SAMPLEs, asks `forge` (with that SAMPLE's frame) what to inject; once only. With `key_file`
// the board has that key (as flash --key leaves it) and the recorder signs with it.
ForgedRun record_with_forgery(const TempDir& dir, const std::function<Injection(const proto::Decoder&)>& forge,
                              const std::string& key_file = "") {
    host::io::PtyBoardOptions options = paced_board(4.0, 120.0);
    options.truth_log = dir.file("truth.csv");
    std::vector<std::string> args = {"record",     "--port", "",   "--stream",         "0.1",
                                     "--duration", "20",     "-o", dir.file("rec.csv")};
    if (!key_file.empty()) {
        options.eeprom = sim::eeprom_image({}, host::io::read_key_file(key_file));
        args.insert(args.end(), {"--key", key_file});
    }
    BoardThread board(options);
    int samples = 0;
    ForgedRun run;
    {
        PtyRelay relay(board.path(), [&](const proto::Decoder& frame) {
            if (frame.type() != proto::MsgType::sample || ++samples != kSamplesBeforeForgery) return Injection{};
            return forge(frame);
        });
        args[2] = relay.path();
        run.record = run_driftlab(args, dir.path());
        run.injected = relay.injected_to_host() + relay.injected_to_board();
    }
    board.stop();  // the ground truth is flushed once a second: stop the board so all of it is on disk
    run.truth = host::read_log(dir.file("truth.csv"));
    return run;
}

// Rows of `truth` whose tick lies within the log's first and last rows'.
std::size_t truth_rows_within(const host::LogData& log, const host::LogData& truth) {
    const auto& ticks = log.optional_columns.at("tick");
    const auto& truth_ticks = truth.optional_columns.at("tick");
    std::size_t n = 0;
    for (const double t : truth_ticks) n += t >= ticks.front() && t <= ticks.back();
    return n;
}

proto::SamplePayload sample_of(const proto::Decoder& frame) {
    proto::SamplePayload s{};
    EXPECT_TRUE(proto::parse(frame.payload(), frame.payload_len(), &s));
    return s;
}

// The recording went on: exit 0, every row one the board sent, `missing` of them left out, the summary naming `what`
// (and the log `noted`, unless empty), and the capture rebuilding the same log.
void expect_recording_went_on(const TempDir& dir, const ForgedRun& run, std::size_t missing, const std::string& what,
                              const std::string& noted) {
    ASSERT_EQ(run.record.exit_code, 0) << run.record.output;
    EXPECT_EQ(run.injected, 1);
    const host::LogData log = host::read_log(dir.file("rec.csv"));
    ASSERT_GT(log.size(), 100u);
    expect_rows_in_truth(log, run.truth);
    EXPECT_EQ(log.size() + missing, truth_rows_within(log, run.truth));
    EXPECT_NE(run.record.output.find(what), std::string::npos) << run.record.output;
    if (!noted.empty()) {
        EXPECT_NE(read_text(dir.file("rec.csv")).find(noted), std::string::npos);
    }
    const RunResult d = run_driftlab({"decode", dir.file("rec.csv.cap"), "-o", dir.file("decoded.csv")}, dir.path());
    ASSERT_EQ(d.exit_code, 0) << d.output;
    EXPECT_EQ(read_text(dir.file("decoded.csv")), read_text(dir.file("rec.csv")));
    EXPECT_NE(d.output.find(what), std::string::npos) << d.output;
}

}  // namespace

// A CONFIG with raw codes on and another window, with the seq the board's next output carries: it had stopped the
// recording ("log row has 9 optional values, header has 4", exit 2).
TEST(RecordForged, AForgedConfigIsReportedAndEveryRealRowKept) {
    TempDir dir("forgedconfig");
    const ForgedRun run = record_with_forgery(dir, [](const proto::Decoder& frame) {
        const proto::ConfigPayload forged{100, 8, 4, 0, static_cast<std::uint8_t>(proto::OutputMode::stream), 1};
        return Injection{frame_of(proto::MsgType::config, static_cast<std::uint16_t>(frame.seq() + 1), forged), {}};
    });
    expect_recording_went_on(dir, run, 0, "1 CONFIG differing from the handshake's ignored", "# unexpected: CONFIG ");
}

// A VERSION claiming a tick of 0 Hz had made every later t_s infinite.
TEST(RecordForged, AForgedVersionIsReportedAndEveryRealRowKept) {
    TempDir dir("forgedversion");
    const ForgedRun run = record_with_forgery(dir, [](const proto::Decoder& frame) {
        proto::VersionPayload forged{};
        forged.proto_version = proto::kProtocolVersion;
        forged.adc_bits = 10;
        forged.channel_count = kChannelCount;
        return Injection{frame_of(proto::MsgType::version, static_cast<std::uint16_t>(frame.seq() + 1), forged), {}};
    });
    expect_recording_went_on(dir, run, 0, "1 VERSION", "# unexpected: VERSION ");
}

// A SAMPLE with the seq and tick of the board's next output, arriving first, had replaced it in the log (the real one
// dropped as a "duplicate"). Neither can be told from the other: both stay out, and the summary says so.
TEST(RecordForged, AForgedNextSampleKeepsItselfAndTheRealOneOutAndIsReported) {
    TempDir dir("forgedsample");
    const ForgedRun run = record_with_forgery(dir, [](const proto::Decoder& frame) {
        proto::SamplePayload forged = sample_of(frame);
        forged.tick += kTicksPerOutput;
        for (auto& v : forged.value_q8) v = 900 * 256;
        return Injection{frame_of(proto::MsgType::sample, static_cast<std::uint16_t>(frame.seq() + 1), forged), {}};
    });
    expect_recording_went_on(dir, run, 1,
                             "1 shared its seq with another of other content (neither used; 1 row kept out)", "");
}

// A CONFIG_SET sent to the board by someone else, which the board obeys and acknowledges: the rows after it would
// follow a window the log does not state. The recording stops with exit 6, its log whole up to there.
// A board without a key obeys anyone's CONFIG_SET (docs/security.md): the recording stops, its log whole.
TEST(RecordForged, AConfigSetFromAnotherTransmitterStopsTheRecordingWithExit6AndAWholeLog) {
    TempDir dir("forgedconfigset");
    const ForgedRun run = record_with_forgery(dir, [](const proto::Decoder&) {
        const proto::ConfigPayload other{100, 8, 4, 1, static_cast<std::uint8_t>(proto::OutputMode::stream), 0};
        return Injection{{}, frame_of(proto::MsgType::config_set, 4242, other)};
    });
    EXPECT_EQ(run.record.exit_code, 6) << run.record.output;
    EXPECT_NE(run.record.output.find("reconfigured"), std::string::npos) << run.record.output;
    const host::LogData log = host::read_log(dir.file("rec.csv"));  // whole: no cut line to drop
    ASSERT_GE(log.size(), static_cast<std::size_t>(kSamplesBeforeForgery) - 5);
    expect_rows_in_truth(log, run.truth);
    EXPECT_EQ(log.size(), truth_rows_within(log, run.truth));
    EXPECT_NE(read_text(dir.file("rec.csv")).find("# unexpected: ACK of a CONFIG_SET"), std::string::npos);
    const RunResult d = run_driftlab({"decode", dir.file("rec.csv.cap"), "-o", dir.file("decoded.csv")}, dir.path());
    ASSERT_EQ(d.exit_code, 0) << d.output;
    EXPECT_EQ(read_text(dir.file("decoded.csv")), read_text(dir.file("rec.csv")));
}

// A board with a key refuses the same CONFIG_SET (NAK unauthenticated): it changes nothing, and the recording goes on
// with every row the board sent.
TEST(RecordForged, AConfigSetFromAnotherTransmitterIsRefusedByAKeyedBoardAndTheRecordingGoesOn) {
    TempDir dir("forgedkeyed");
    ASSERT_EQ(run_driftlab({"keygen", "-o", dir.file("board.key")}, dir.path()).exit_code, 0);
    const ForgedRun run = record_with_forgery(
        dir,
        [](const proto::Decoder&) {
            const proto::ConfigPayload other{100, 8, 4, 1, static_cast<std::uint8_t>(proto::OutputMode::stream), 0};
            return Injection{{}, frame_of(proto::MsgType::config_set, 4242, other)};
        },
        dir.file("board.key"));
    expect_recording_went_on(dir, run, 0, "lost 0 (0.000 %", "");
    EXPECT_EQ(read_text(dir.file("rec.csv")).find("# unexpected: ACK"), std::string::npos);
}
