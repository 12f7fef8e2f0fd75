// `driftlab record` refuses what is not a driftlab board of protocol v1: a clear message and exit code 4.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>

#include "driftlab/proto/decoder.hpp"
#include "driftlab/proto/encoder.hpp"
#include "driftlab/proto/messages.hpp"
#include "driftlab/proto/status.hpp"
#include "driftlab/proto/wire.hpp"
#include "host/io/capture.hpp"
#include "host/io/pty_bridge.hpp"
#include "tests/e2e/e2e_support.hpp"

using namespace driftlab;
using namespace driftlab::e2e;

namespace {

constexpr int kDeviceErrorExit = 4;

// Something on a pseudo-terminal that answers every write with `answer(bytes written, count)`.
class FakeDevice {
public:
    using Answer = std::function<std::vector<std::uint8_t>(const std::uint8_t*, std::size_t)>;
    explicit FakeDevice(Answer answer) : answer_(std::move(answer)) {
        thread_ = std::thread([this] {
            std::uint8_t buf[256];
            while (!stop_.load()) {
                if (const std::size_t n = bridge_.read(buf, sizeof buf, 10); n > 0) {
                    const auto out = answer_(buf, n);
                    bridge_.write(out.data(), out.size());
                }
            }
        });
    }
    ~FakeDevice() {
        stop_.store(true);
        thread_.join();
    }
    std::string path() const { return bridge_.slave_path(); }

private:
    host::io::PtyBridge bridge_;
    Answer answer_;
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

// A protocol v1 board that takes any configuration and reads it back, but refuses every POLL as a streaming board
// does (docs/protocol.md §3.5): what the recorder meets when something else switched the board to stream mode.
class PollRefusingBoard {
public:
    std::vector<std::uint8_t> operator()(const std::uint8_t* in, std::size_t n) {
        std::vector<std::uint8_t> out;
        for (std::size_t i = 0; i < n; ++i) {
            if (!decoder_.feed(in[i])) continue;
            do answer(out);
            while (decoder_.next());
        }
        return out;
    }

private:
    void answer(std::vector<std::uint8_t>& out) {
        std::uint8_t f[proto::kMaxFrameSize];
        std::size_t size = 0;
        const std::uint16_t seq = seq_++;
        switch (decoder_.type()) {
        case proto::MsgType::hello: {
            proto::VersionPayload v{};
            v.proto_version = proto::kProtocolVersion;
            v.adc_bits = 10;
            v.vref_mv = 5000;
            v.tick_hz = 250000;
            v.channel_count = 4;
            size = proto::encode_version(v, seq, f, sizeof f);
            break;
        }
        case proto::MsgType::status_get: size = proto::encode_status(proto::StatusPayload{}, seq, f, sizeof f); break;
        case proto::MsgType::config_set:
            EXPECT_TRUE(proto::parse(decoder_.payload(), decoder_.payload_len() - proto::kAuthTrailerBytes, &config_));
            size = proto::encode_ack({decoder_.type_id(), decoder_.seq()}, seq, f, sizeof f);
            break;
        case proto::MsgType::config_get: size = proto::encode_config(config_, seq, f, sizeof f); break;
        case proto::MsgType::poll:
            size = proto::encode_nak({decoder_.type_id(), decoder_.seq(),
                                      static_cast<std::uint8_t>(proto::Status::not_allowed), proto::kNakFieldNone},
                                     seq, f, sizeof f);
            break;
        default: break;
        }
        out.insert(out.end(), f, f + size);
    }

    proto::Decoder decoder_;
    proto::ConfigPayload config_{};
    std::uint16_t seq_ = 0;
};

void expect_refused(const RunResult& r, const std::string& words, const TempDir& dir) {
    EXPECT_EQ(r.exit_code, kDeviceErrorExit) << r.output;
    EXPECT_NE(r.output.find(words), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("rec.csv")));
    EXPECT_FALSE(std::filesystem::exists(dir.file("rec.csv.cap")));
}

}  // namespace

TEST(RecordErrors, MissingPortNamesThePath) {
    TempDir dir("noport");
    const RunResult r = run_driftlab({"record", "--port", dir.file("ttyNONE"), "-o", dir.file("rec.csv")}, dir.path());
    expect_refused(r, dir.file("ttyNONE") + ": cannot open", dir);
}

// The output folders are made, or refused, before the port is opened (opening resets an Arduino): a file where a
// folder must go is named with exit 4 although the port (missing here) would be refused too.
TEST(RecordErrors, AnOutputFolderThatCannotBeMadeIsNamedBeforeThePort) {
    TempDir dir("blockedfolder");
    std::ofstream(dir.file("blocked")) << "a file, not a folder\n";
    const std::string port = dir.file("ttyNONE");
    const RunResult log = run_driftlab({"record", "--port", port, "-o", dir.file("blocked/rec.csv")}, dir.path());
    EXPECT_EQ(log.exit_code, kDeviceErrorExit) << log.output;
    EXPECT_NE(log.output.find(dir.file("blocked") + ": cannot create the log folder"), std::string::npos) << log.output;
    const RunResult capture = run_driftlab(
        {"record", "--port", port, "-o", dir.file("rec.csv"), "--capture", dir.file("blocked/rec.cap")}, dir.path());
    EXPECT_EQ(capture.exit_code, kDeviceErrorExit) << capture.output;
    EXPECT_NE(capture.output.find(dir.file("blocked") + ": cannot create the capture folder"), std::string::npos)
        << capture.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("rec.csv")));
}

// Folders made for a run that is then refused are taken away again (they had been left behind, empty), and only
// those: a folder that was there before stays, empty as it is.
TEST(RecordErrors, ARefusedRunRemovesOnlyTheFoldersItMade) {
    TempDir dir("refusedfolders");
    std::filesystem::create_directory(dir.file("before"));
    host::io::PtyBridge silent;
    for (const std::string& port : {dir.file("ttyNONE"), silent.slave_path()}) {
        const RunResult r = run_driftlab({"record", "--port", port, "-o", dir.file("before/new/deeper/rec.csv"),
                                          "--capture", dir.file("cap/rec.cap")},
                                         dir.path());
        EXPECT_EQ(r.exit_code, kDeviceErrorExit) << r.output;
        EXPECT_TRUE(std::filesystem::is_directory(dir.file("before"))) << port;
        EXPECT_FALSE(std::filesystem::exists(dir.file("before/new"))) << port;
        EXPECT_FALSE(std::filesystem::exists(dir.file("cap"))) << port;
    }
    // A folder the run made that holds something else by then is kept with it.
    std::filesystem::create_directories(dir.file("before/new"));
    std::ofstream(dir.file("before/new/notes.txt")) << "mine\n";
    const RunResult r =
        run_driftlab({"record", "--port", dir.file("ttyNONE"), "-o", dir.file("before/new/rec.csv")}, dir.path());
    EXPECT_EQ(r.exit_code, kDeviceErrorExit) << r.output;
    EXPECT_EQ(read_text(dir.file("before/new/notes.txt")), "mine\n");
}

// An earlier recording is not replaced by running the command again (an hour's log and its capture had been
// truncated without a word): refused before the port, exit 2, both files kept; --overwrite lets the run go on (to
// the missing port here).
TEST(RecordErrors, AnEarlierRecordingIsKeptUnlessOverwriteIsGiven) {
    TempDir dir("earlier");
    const std::string port = dir.file("ttyNONE");
    const std::string log = dir.file("run.csv");
    std::ofstream(log) << "an hour of rows\n";
    const RunResult again = run_driftlab({"record", "--port", port, "-o", log}, dir.path());
    EXPECT_EQ(again.exit_code, 2) << again.output;
    EXPECT_NE(again.output.find(log + ": a log is already there; name another -o, or pass --overwrite"),
              std::string::npos)
        << again.output;
    EXPECT_EQ(read_text(log), "an hour of rows\n");

    const std::string other = dir.file("other.csv");
    std::ofstream(other + ".cap") << "its capture\n";
    const RunResult capture = run_driftlab({"record", "--port", port, "-o", other}, dir.path());
    EXPECT_EQ(capture.exit_code, 2) << capture.output;
    EXPECT_NE(capture.output.find(other + ".cap: a capture is already there; name another --capture"),
              std::string::npos)
        << capture.output;
    EXPECT_FALSE(std::filesystem::exists(other));
    EXPECT_EQ(read_text(other + ".cap"), "its capture\n");

    const RunResult overwrite = run_driftlab({"record", "--port", port, "-o", log, "--overwrite"}, dir.path());
    EXPECT_EQ(overwrite.exit_code, kDeviceErrorExit) << overwrite.output;
    EXPECT_NE(overwrite.output.find(port + ": cannot open"), std::string::npos) << overwrite.output;
}

// A configuration the firmware would refuse, or a period that is not one, is the command line's fault and is
// refused before the port is opened (a missing port here would otherwise give exit 4): --stream -1 had recorded in
// poll mode at 0.1 s, 0.0105 had been rounded to 10 ms, and 10 ms with 25 conversions had come back from the board
// as a device error naming only the field.
TEST(RecordErrors, ABadPeriodOrConfigurationIsAUsageErrorBeforeThePort) {
    TempDir dir("badconfig");
    const std::string port = dir.file("ttyNONE");
    for (const char* bad : {"-1", "0"}) {
        const RunResult r =
            run_driftlab({"record", "--port", port, "--stream", bad, "-o", dir.file("rec.csv")}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.output;
    }
    const RunResult odd =
        run_driftlab({"record", "--port", port, "--poll", "0.0105", "-o", dir.file("rec.csv")}, dir.path());
    EXPECT_EQ(odd.exit_code, 2) << odd.output;
    EXPECT_NE(odd.output.find("--poll: expected a whole number of milliseconds in [0.01, 60] s, got 0.0105"),
              std::string::npos)
        << odd.output;
    const RunResult fast =
        run_driftlab({"record", "--port", port, "--stream", "0.01", "-o", dir.file("rec.csv")}, dir.path());
    EXPECT_EQ(fast.exit_code, 2) << fast.output;
    EXPECT_NE(fast.output.find("conversions_per_output: the firmware refuses this configuration (out_of_range): "
                               "output_period_ms 10 / (4 channels x conversions_per_output 25)"),
              std::string::npos)
        << fast.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("rec.csv")));
}

TEST(RecordErrors, AFileThatIsNotATerminalIsRefused) {
    TempDir dir("notatty");
    const RunResult r = run_driftlab({"record", "--port", "/dev/null", "-o", dir.file("rec.csv")}, dir.path());
    expect_refused(r, "not a serial port", dir);
}

TEST(RecordErrors, ASilentDeviceIsNotADriftlabBoard) {
    TempDir dir("silent");
    host::io::PtyBridge silent;
    const RunResult r = run_driftlab({"record", "--port", silent.slave_path(), "-o", dir.file("rec.csv")}, dir.path());
    expect_refused(r, "no answer to HELLO", dir);
}

TEST(RecordErrors, ADeviceAnsweringGarbageIsNotADriftlabBoard) {
    TempDir dir("garbage");
    std::mt19937 rng(7);
    FakeDevice garbage([&](const std::uint8_t*, std::size_t) {
        std::vector<std::uint8_t> out(64);
        for (auto& b : out) b = static_cast<std::uint8_t>(rng());
        return out;
    });
    const RunResult r = run_driftlab({"record", "--port", garbage.path(), "-o", dir.file("rec.csv")}, dir.path());
    expect_refused(r, "no valid driftlab frame", dir);
}

// A refused POLL ends the recording (exit 4) with the reason and the row count, the log and capture kept: the rows
// of a board that streams after all would not be the polled log asked for.
TEST(RecordErrors, ABoardRefusingPollEndsTheRecordingNamingStreamMode) {
    TempDir dir("pollrefused");
    FakeDevice board(PollRefusingBoard{});
    const std::string out = dir.file("driftlab.out");
    const pid_t pid =
        spawn_driftlab({"record", "--port", board.path(), "--poll", "0.1", "-o", dir.file("rec.csv")}, out);
    // A recorder that ignored the refusals would poll until stopped: after 10 s it is (exit 0, failing below).
    siginfo_t ended{};
    for (int i = 0; i < 1000 && ended.si_pid != pid; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        static_cast<void>(::waitid(P_PID, static_cast<id_t>(pid), &ended, WEXITED | WNOHANG | WNOWAIT));
    }
    if (ended.si_pid != pid) ::kill(pid, SIGINT);
    const RunResult r = wait_child(pid, out);
    EXPECT_EQ(r.exit_code, kDeviceErrorExit) << r.output;
    EXPECT_NE(r.output.find(board.path() + ": the board refused POLL (NAK not_allowed): it is in stream mode"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(dir.file("rec.csv") + " keeps the 0 rows recorded before)"), std::string::npos) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir.file("rec.csv")));
    EXPECT_NE(read_text(dir.file("rec.csv.cap")).find("the board refused POLL"), std::string::npos);
}

TEST(RecordErrors, ABoardOfAnotherProtocolVersionIsRefusedByNumber) {
    TempDir dir("version");
    FakeDevice future([](const std::uint8_t*, std::size_t) {
        proto::VersionPayload v{};
        v.proto_version = 3;
        v.tick_hz = 250000;
        std::vector<std::uint8_t> out(64);
        out.resize(proto::encode_version(v, 0, out.data(), out.size()));
        out[proto::kOffsetVersion] = 3;  // a version-3 frame header, as a newer firmware would send
        return out;
    });
    const RunResult r = run_driftlab({"record", "--port", future.path(), "-o", dir.file("rec.csv")}, dir.path());
    expect_refused(r, "protocol version 3", dir);
}

TEST(RecordErrors, AVersionOneBoardInPollModeIsFoundByItsOwnHelloAndNamed) {
    // A v1 board ignores v2 frames and answers only a v1 HELLO, with its v1 VERSION.
    TempDir dir("version1");
    FakeDevice old([](const std::uint8_t* bytes, std::size_t n) {
        std::vector<std::uint8_t> out;
        if (n < proto::kFrameOverhead || bytes[proto::kOffsetVersion] != proto::kLegacyProtocolVersion) return out;
        proto::VersionPayload v{};
        v.proto_version = 1;
        v.tick_hz = 250000;
        out.resize(proto::kMaxFrameSize);
        out.resize(proto::encode_legacy_version(v, 0, out.data(), out.size()));
        return out;
    });
    const RunResult r = run_driftlab({"record", "--port", old.path(), "-o", dir.file("rec.csv")}, dir.path());
    expect_refused(r, "the board speaks protocol version 1; this driftlab speaks version 2", dir);
}

namespace driftlab::e2e {
namespace {

// A capture whose start comes before any VERSION or CONFIG (frames lost to damage): decode names the file it was
// given and the byte offset, not the name the capture's header carries (the recording's, before it was renamed).
TEST(DecodeErrors, AStartWithoutTheBoardsFramesNamesTheFileAndOffset) {
    TempDir dir("decodestart");
    const std::string renamed = dir.file("renamed.cap");
    std::uint64_t start_offset = 0;
    {
        host::io::CaptureWriter w(renamed, {{"port", "/dev/pts/3"}, {"capture", "original.cap"}});
        start_offset = std::filesystem::file_size(renamed);
        w.write_event("start");
    }
    const RunResult r = run_driftlab({"decode", renamed, "-o", dir.file("made/x.csv")}, dir.path());
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("made")));  // the folder it made for no log is taken away
    EXPECT_NE(r.output.find("renamed.cap: byte offset " + std::to_string(start_offset) + ": recording started before"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("original.cap"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace driftlab::e2e
