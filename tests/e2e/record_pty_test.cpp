// `driftlab record` through a pseudo-terminal against the native firmware (host/io/pty_board), compared with
// the ground truth the board side decoded from the firmware's own output.
#include <gtest/gtest.h>

#include <signal.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "driftlab/proto/decoder.hpp"
#include "host/io/capture.hpp"
#include "host/io/recorder.hpp"
#include "host/log/log_reader.hpp"
#include "tests/e2e/e2e_support.hpp"

using namespace driftlab;
using namespace driftlab::e2e;

namespace {

// `decode run.csv.cap -o run.csv` of a damaged capture had replaced the intact recording beside it; a frame failing
// its CRC in a damaged copy had been counted only as a lost sequence number, like a radio loss.
void expect_decode_keeps_logs_and_names_crc_failures(const TempDir& dir, const std::string& log) {
    const std::string recorded = read_text(log);
    const RunResult again = run_driftlab({"decode", log + ".cap", "-o", log}, dir.path());
    EXPECT_EQ(again.exit_code, 2) << again.output;
    EXPECT_NE(again.output.find("a log is already there"), std::string::npos) << again.output;
    EXPECT_EQ(read_text(log), recorded);

    // Its folder is made; with --overwrite it replaces; to standard output the log alone (the summary on stderr).
    const std::string nested = dir.file("sub/dir/decoded.csv");
    ASSERT_EQ(run_driftlab({"decode", log + ".cap", "-o", nested}, dir.path()).exit_code, 0);
    std::ofstream(nested) << "stale";
    const RunResult replaced = run_driftlab({"decode", log + ".cap", "-o", nested, "--overwrite"}, dir.path());
    ASSERT_EQ(replaced.exit_code, 0) << replaced.output;
    EXPECT_EQ(read_text(nested), recorded);
    std::ofstream(dir.file("out.csv")).close();  // standard output is opened there, not created
    const RunResult to_stdout =
        run_driftlab_stdout_to({"decode", log + ".cap", "-o", "-"}, dir.file("out.csv"), dir.path());
    ASSERT_EQ(to_stdout.exit_code, 0) << to_stdout.output;
    EXPECT_EQ(read_text(dir.file("out.csv")), recorded);
    EXPECT_NE(to_stdout.output.find("to standard output"), std::string::npos) << to_stdout.output;

    // The last byte of the tenth frame received, found by decoding the capture's received bytes: its CRC.
    std::string capture = read_text(log + ".cap");
    std::uint64_t record_offset = 0;
    std::size_t last_byte = 0;
    {
        host::io::CaptureReader reader(log + ".cap");
        proto::Decoder decoder;
        int frames = 0;
        while (const auto record = reader.next()) {
            if (record->kind != host::io::CaptureKind::rx) continue;
            for (std::size_t i = 0; i < record->payload.size() && frames < 10; ++i) {
                if (!decoder.feed(record->payload[i])) continue;
                for (bool more = true; more; more = decoder.next()) ++frames;
                if (frames >= 10) record_offset = record->offset, last_byte = record->offset + 1 + 8 + 4 + i;
            }
        }
    }
    ASSERT_GT(last_byte, 0u);
    capture[last_byte] = static_cast<char>(capture[last_byte] ^ 0x10);
    std::ofstream(dir.file("crc.cap"), std::ios::binary) << capture;
    const RunResult crc = run_driftlab({"decode", dir.file("crc.cap"), "-o", dir.file("crc.csv")}, dir.path());
    ASSERT_EQ(crc.exit_code, 0) << crc.output;
    EXPECT_NE(crc.output.find("crc.cap: 1 frame failed its CRC check and counts as lost (in the record at byte "
                              "offset " +
                              std::to_string(record_offset) + ")\n"),
              std::string::npos)
        << crc.output;
    EXPECT_NE(crc.output.find("crc errors 1)"), std::string::npos) << crc.output;
}

// `driftlab hil --pty` started with `args`: its process, and the line that names the pseudo-terminal it serves
// ("/dev/pts/N", or "LINK -> /dev/pts/N" with --pty-link), empty when none came within 5 s.
std::pair<pid_t, std::string> serve_hil_pty(const std::vector<std::string>& args, const std::string& output_file) {
    std::vector<std::string> all = {"hil", "--pty"};
    all.insert(all.end(), args.begin(), args.end());
    const pid_t hil = spawn_driftlab(all, output_file);
    std::string path;
    for (int i = 0; i < 500 && path.empty(); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        std::istringstream lines(read_text(output_file));
        for (std::string line; path.empty() && std::getline(lines, line) && !lines.eof();)
            if (line.rfind("/dev/", 0) == 0 || line.find(" -> /dev/") != std::string::npos) path = line;
    }
    return {hil, path};
}

// `driftlab record ARGS` against the `hil --pty` process `hil` (its output in DIR/hil.out), which is then ended.
RunResult record_then_end_hil(const std::vector<std::string>& args, pid_t hil, const TempDir& dir) {
    const RunResult r = run_driftlab(args, dir.path());
    ::kill(hil, SIGTERM);
    static_cast<void>(wait_child(hil, dir.file("hil.out")));
    return r;
}

}  // namespace

TEST(RecordPty, StreamedSixtySecondsEqualWhatTheBoardSentAndDecodeRebuildsTheLog) {
    TempDir dir("stream60");
    // 4x the wall clock: faster pacing lets a busy machine (ctest -j) leave the recorder unscheduled long enough
    // for the pseudo-terminal's buffer to fill, and the board then drops bytes as a real UART would.
    host::io::PtyBoardOptions board_opts = paced_board(4.0, 90.0);
    board_opts.truth_log = dir.file("truth.csv");
    BoardThread board(board_opts);
    const std::string log = dir.file("rec.csv");
    const RunResult r = run_driftlab({"record", "--port", board.path(), "--stream", "0.1", "--duration", "60",
                                      "--window", "16", "--order", "1", "-o", log},
                                     dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    board.join();

    const host::LogData rec = host::read_log(log);
    const host::LogData truth = host::read_log(dir.file("truth.csv"));
    // 60 s at 0.1 s, both ends included; nothing lost on a pseudo-terminal.
    EXPECT_GE(rec.size(), 601u);
    ASSERT_GT(rec.size(), 1u);
    EXPECT_GE(rec.t_s.back() - rec.t_s.front(), 60.0 - 1e-9);
    EXPECT_EQ(rec.metadata.get("mode"), "stream");
    EXPECT_EQ(rec.metadata.get_int("window"), 16);
    EXPECT_EQ(rec.metadata.get_int("fit_order"), 1);
    EXPECT_EQ(rec.metadata.get_int("tick_hz"), 250000);
    EXPECT_EQ(rec.metadata.get("port"), board.path());
    // The header names the recorder as --version does (both the CMake project's version, not a copy of it).
    const RunResult version = run_driftlab({"--version"}, dir.path());
    ASSERT_EQ(version.exit_code, 0) << version.output;
    EXPECT_EQ(rec.metadata.get("recorder").value_or("") + "\n", version.output);
    EXPECT_EQ(version.output.rfind("driftlab ", 0), 0u) << version.output;
    expect_rows_in_truth(rec, truth);
    // Consecutive rows are consecutive outputs of the firmware: one period apart, seq +1.
    for (std::size_t i = 1; i < rec.size(); ++i) {
        EXPECT_NEAR(rec.t_s[i] - rec.t_s[i - 1], 0.1, 1e-9) << "row " << i;
        EXPECT_EQ(rec.seq[i], rec.seq[i - 1] + 1) << "row " << i;
    }

    const RunResult d = run_driftlab({"decode", log + ".cap", "-o", dir.file("decoded.csv")}, dir.path());
    ASSERT_EQ(d.exit_code, 0) << d.output;
    EXPECT_EQ(read_text(dir.file("decoded.csv")), read_text(log));
    expect_decode_keeps_logs_and_names_crc_failures(dir, log);

    // One flipped bit in the start event's text ("start" -> "stcrt": events carry no checksum) had left the capture
    // undecodable; it is read as the start, with a warning naming its offset, and rebuilds the same log. Two bits
    // off is no longer taken for it.
    std::uint64_t start_offset = 0;
    {
        host::io::CaptureReader reader(log + ".cap");
        while (const auto record = reader.next())
            if (record->kind == host::io::CaptureKind::event && record->text() == "start")
                start_offset = record->offset;
    }
    ASSERT_GT(start_offset, 0u);
    const std::string capture = read_text(log + ".cap");
    const std::size_t letter_a = start_offset + 1 + 8 + 4 + 2;  // kind, time, length, then "st" of "start"
    ASSERT_EQ(capture.substr(letter_a - 2, 5), "start");
    const auto damaged_copy = [&](const std::string& name, char replacement) {
        std::string bytes = capture;
        bytes[letter_a] = replacement;
        std::ofstream(dir.file(name), std::ios::binary) << bytes;
        return dir.file(name);
    };
    const RunResult one_bit =
        run_driftlab({"decode", damaged_copy("one.cap", 'c'), "-o", dir.file("one.csv")}, dir.path());
    ASSERT_EQ(one_bit.exit_code, 0) << one_bit.output;
    EXPECT_NE(one_bit.output.find("one.cap: byte offset " + std::to_string(start_offset) +
                                  ": event 'stcrt' read as the recording's start"),
              std::string::npos)
        << one_bit.output;
    EXPECT_EQ(read_text(dir.file("one.csv")), read_text(log));
    const RunResult two_bits =
        run_driftlab({"decode", damaged_copy("two.cap", 'b'), "-o", dir.file("two.csv")}, dir.path());
    EXPECT_EQ(two_bits.exit_code, 3) << two_bits.output;  // 'a' ^ 'b' = 3: two bits
    EXPECT_NE(two_bits.output.find("no recording start"), std::string::npos) << two_bits.output;
}

TEST(RecordPty, PolledRecordingHoldsExactlyTheAnswersTheBoardSent) {
    TempDir dir("poll");
    host::io::PtyBoardOptions board_opts = paced_board(1.0, 30.0);
    board_opts.truth_log = dir.file("truth.csv");
    BoardThread board(board_opts);
    const std::string log = dir.file("rec.csv");
    const RunResult r = run_driftlab(
        {"record", "--port", board.path(), "--poll", "0.1", "--duration", "2", "--raw", "-o", log}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // The ground truth is flushed once a second while the board runs: stop it so every answer is on disk.
    board.stop();
    const host::LogData rec = host::read_log(log);
    const host::LogData truth = host::read_log(dir.file("truth.csv"));
    EXPECT_GE(rec.size(), 21u);
    expect_rows_in_truth(rec, truth);
    ASSERT_TRUE(rec.has_column("raw_gyro"));
    for (std::size_t i = 0; i < rec.size(); ++i) {
        EXPECT_EQ(rec.optional_columns.at("flags")[i], 0.0) << "RAW lost at row " << i;
        // The raw code is one of the conversions the least-squares estimate was made from.
        EXPECT_GE(rec.optional_columns.at("raw_gyro")[i], 498.0);
        EXPECT_LE(rec.optional_columns.at("raw_gyro")[i], 506.0);
    }
    EXPECT_EQ(rec.metadata.get("mode"), "poll");
}

TEST(RecordPty, SigkillLeavesAReadableLogAndTheCaptureRebuildsEveryCompleteLine) {
    TempDir dir("kill");
    host::io::PtyBoardOptions board_opts = paced_board(10.0, 600.0);
    BoardThread board(board_opts);
    const std::string log = dir.file("rec.csv");
    const pid_t pid =
        spawn_driftlab({"record", "--port", board.path(), "--stream", "0.02", "-o", log}, dir.file("record.out"));
    // Let it record a few flush intervals (until more than 50 rows are on disk, however loaded the machine; at most
    // a minute), then kill it without a chance to clean up.
    const auto rows_on_disk = [&] {
        const auto lines = lines_of(read_text(log));
        return std::count_if(lines.begin(), lines.end(),
                             [](const std::string& l) { return !l.empty() && l[0] != '#'; }) -
               1;
    };
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (rows_on_disk() <= 50 && std::chrono::steady_clock::now() < give_up)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    ::kill(pid, SIGKILL);
    const RunResult r = wait_child(pid, dir.file("record.out"));
    ASSERT_EQ(r.exit_code, -1);

    host::ReadOptions lenient;
    lenient.drop_truncated_tail = true;
    const host::LogData killed = host::read_log(log, lenient);
    EXPECT_GT(killed.size(), 50u);

    const RunResult d = run_driftlab({"decode", log + ".cap", "-o", dir.file("decoded.csv")}, dir.path());
    ASSERT_EQ(d.exit_code, 0) << d.output;
    const auto killed_lines = lines_of(read_text(log));
    const auto decoded_lines = lines_of(read_text(dir.file("decoded.csv")));
    ASSERT_GE(decoded_lines.size(), killed_lines.size());
    for (std::size_t i = 0; i < killed_lines.size(); ++i)
        EXPECT_EQ(killed_lines[i], decoded_lines[i]) << "line " << i + 1;
    EXPECT_NO_THROW(host::read_log(dir.file("decoded.csv")));
}

// The board's pseudo-terminal is closed under the recorder for 6 s of board time and opened again: the recorder
// must reconnect, record the loss as a gap and lose nothing else (docs/recording.md "Durability").
TEST(RecordPty, UnplugAndReplugIsSurvivedWithTheGapRecorded) {
    TempDir dir("unplug");
    host::io::PtyBoardOptions board_opts = paced_board(4.0, 120.0);
    board_opts.link_path = dir.file("board-link");
    board_opts.truth_log = dir.file("truth.csv");
    board_opts.unplugs = {{6.0, 6.0}};
    BoardThread board(board_opts);
    const std::string link = board.path();
    const std::string log = dir.file("rec.csv");
    const RunResult r =
        run_driftlab({"record", "--port", link, "--stream", "0.1", "--duration", "16", "-o", log}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("reconnects 1"), std::string::npos) << r.output;
    board.stop();  // its ground truth is flushed once a second while it runs

    const host::LogData rec = host::read_log(log);
    const host::LogData truth = host::read_log(dir.file("truth.csv"));
    ASSERT_EQ(rec.gaps.size(), 1u);
    EXPECT_NE(rec.gaps[0].text.find("link lost after t_s="), std::string::npos) << rec.gaps[0].text;
    EXPECT_NE(rec.gaps[0].text.find(" (board clock), "), std::string::npos) << rec.gaps[0].text;
    EXPECT_NE(rec.gaps[0].text.find(" s (host clock), "), std::string::npos) << rec.gaps[0].text;
    const std::size_t k = rec.gaps[0].before_row;
    ASSERT_GT(k, 0u);
    ASSERT_LT(k, rec.size());
    // The board streamed on while unplugged: the jump in seq is the outputs it sent meanwhile plus those replies to
    // the recorder's handshake on reconnecting (VERSION, ACK of CONFIG_SET, CONFIG, STATUS) that came before the
    // first row after the gap: all four, unless an output slipped between them (a loaded machine), which is then
    // that first row.
    const double missed_outputs = (rec.t_s[k] - rec.t_s[k - 1]) / 0.1 - 1.0;
    EXPECT_GT(missed_outputs, 40.0);
    const double replies_before = static_cast<double>(rec.seq[k] - rec.seq[k - 1] - 1) - missed_outputs;
    EXPECT_NEAR(replies_before, std::round(replies_before), 1e-6);
    EXPECT_GE(std::lround(replies_before), 0);
    EXPECT_LE(std::lround(replies_before), 4);
    expect_rows_in_truth(rec, truth);
}

// While the port is away the status line keeps its cadence (four times a second), with the time since the loss and
// until the next attempt: it had been called once per back-off step, standing still for 2 s here (4 s in a longer
// loss). The recorder runs in this process, to see every call.
TEST(RecordPty, TheStatusKeepsItsCadenceWhileThePortIsAway) {
    TempDir dir("lostcadence");
    host::io::PtyBoardOptions board_opts = paced_board(4.0, 120.0);
    board_opts.link_path = dir.file("board-link");
    board_opts.unplugs = {{4.0, 12.0}};  // 3 s of wall time: reopen attempts 0.25, 0.75, 1.75 and 3.75 s after
    BoardThread board(board_opts);
    host::io::RecordOptions options;
    options.port = board.path();
    options.log_path = dir.file("rec.csv");
    options.duration_s = 20.0;
    options.config.output_period_ms = 100;
    options.config.conversions_per_output = 25;
    options.config.window = 25;
    options.config.mode = static_cast<std::uint8_t>(proto::OutputMode::stream);
    struct Call {
        std::chrono::steady_clock::time_point at;
        host::io::LinkLoss lost;
    };
    std::vector<Call> away;
    const std::atomic<bool> stop{false};
    const host::io::RecordSummary summary = host::io::record(
        options, stop, [&](const host::io::AssemblyStats&, double, const std::optional<host::io::LinkLoss>& lost) {
            if (lost) away.push_back({std::chrono::steady_clock::now(), *lost});
        });
    ASSERT_EQ(summary.reconnects, 1u);
    ASSERT_GE(away.size(), 2u);
    double longest_s = 0.0;
    for (std::size_t i = 1; i < away.size(); ++i) {
        longest_s = std::max(longest_s, std::chrono::duration<double>(away[i].at - away[i - 1].at).count());
        EXPECT_GT(away[i].lost.lost_for_s, away[i - 1].lost.lost_for_s) << "call " << i;
        EXPECT_GE(away[i].lost.next_attempt, away[i - 1].lost.next_attempt) << "call " << i;
    }
    // 0.25 s apart over the 3.75 s (old: 4 calls, the last 1.75 s after the loss, then 2 s without one); a loaded
    // machine may stretch a slice, not to a back-off step.
    EXPECT_GE(away.size(), 10u);
    EXPECT_LT(longest_s, 0.75) << away.size() << " calls while away";
    EXPECT_GE(away.back().lost.lost_for_s, 2.5);
    EXPECT_EQ(away.back().lost.next_attempt, 4);
    for (const Call& c : away) {
        EXPECT_GE(c.lost.next_attempt_in_s, 0.0);
        EXPECT_LE(c.lost.next_attempt_in_s, 2.0);
    }
}

// The log's and the capture's folders are made when missing, as `hil` makes its own: -o into a new folder had
// failed with exit 4 once the port was open ("cannot create the capture"), or, with --capture elsewhere, only after
// the handshake, leaving the capture behind.
TEST(RecordPty, MissingFoldersOfTheLogAndTheCaptureAreMade) {
    TempDir dir("folders");
    host::io::PtyBoardOptions board_opts = paced_board(4.0, 60.0);
    BoardThread board(board_opts);
    const std::string log = dir.file("new/sub/rec.csv");
    const std::string capture = dir.file("captures/rec.cap");
    const RunResult r = run_driftlab(
        {"record", "--port", board.path(), "--stream", "0.1", "--duration", "1", "-o", log, "--capture", capture},
        dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_GE(host::read_log(log).size(), 11u);
    EXPECT_TRUE(std::filesystem::is_regular_file(capture));
}

// --pty-link prints the link and the terminal it points to, so a tool that refuses symlinks gets the /dev/pts path:
// that path is where the link points, and a recorder on it gets the board.
TEST(RecordPty, HilPtyLinkPrintsTheLinkAndTheTerminalItPointsTo) {
    TempDir dir("hilptylink");
    const std::string link = dir.file("imu");
    const auto [hil, line] =
        serve_hil_pty({"--pty-link", link, "--speed", "20", "--duration", "120"}, dir.file("hil.out"));
    ASSERT_FALSE(line.empty()) << read_text(dir.file("hil.out"));
    const std::string prefix = link + " -> ";
    ASSERT_EQ(line.rfind(prefix, 0), 0u) << line;
    const std::string pts = line.substr(prefix.size());
    EXPECT_EQ(pts.rfind("/dev/pts/", 0), 0u) << line;
    EXPECT_EQ(std::filesystem::read_symlink(link).string(), pts);
    const std::string log = dir.file("rec.csv");
    const RunResult r =
        record_then_end_hil({"record", "--port", pts, "--stream", "0.1", "--duration", "2", "-o", log}, hil, dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(host::read_log(log).metadata.get("port"), pts);
}

// A pseudo-terminal does not pace bytes at the model's link.baud, so a model whose link could not carry its outputs
// (20 ms outputs need 1650 bytes/s, 9600 baud carry 960; refused without --pty) is served, and recorded at that rate.
TEST(RecordPty, HilPtyServesAModelWhoseSimulatedLinkCouldNotCarryItsOutputs) {
    TempDir dir("hilptybaud");
    const auto [model, simulated] = plain_hil_with_model(
        dir, "fast.toml", "[firmware]\noutput_period_ms = 20\nconversions_per_output = 5\n\n[link]\nbaud = 9600.0\n");
    ASSERT_EQ(simulated.exit_code, 5) << simulated.output;  // the check still holds where the link is simulated
    const auto [hil, path] = serve_hil_pty({"--model", model, "--speed", "4", "--duration", "60"}, dir.file("hil.out"));
    ASSERT_FALSE(path.empty()) << read_text(dir.file("hil.out"));
    const std::string log = dir.file("rec.csv");
    const RunResult r = record_then_end_hil({"record", "--port", path, "--stream", "0.02", "--conversions", "5",
                                             "--window", "5", "--duration", "1", "-o", log},
                                            hil, dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const host::LogData rec = host::read_log(log);
    ASSERT_GT(rec.size(), 1u);
    EXPECT_GE(rec.t_s.back() - rec.t_s.front(), 1.0 - 1e-9);
    EXPECT_EQ(rec.metadata.get_double("sample_period_s"), 0.02);
}

// `driftlab hil --pty` serves the simulated board itself: its first output line is the path a recorder opens.
TEST(RecordPty, HilPtyServesTheSimulatedBoardToTheRecorder) {
    TempDir dir("hilpty");
    const auto [hil, path] = serve_hil_pty({"--speed", "20", "--duration", "120"}, dir.file("hil.out"));
    ASSERT_FALSE(path.empty()) << read_text(dir.file("hil.out"));
    const std::string log = dir.file("rec.csv");
    const RunResult r =
        record_then_end_hil({"record", "--port", path, "--stream", "0.1", "--duration", "10", "-o", log}, hil, dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const host::LogData rec = host::read_log(log);
    // The recorder stops once its rows span 10 s: outputs 0.1 s apart span at least 101 frames by sequence number.
    // The board is paced at 20x the wall clock, so on a loaded machine its pseudo-terminal can drop a frame
    // (ctest once saw 100 rows); the recorder counts that by seq, and at most one such loss is tolerated here.
    ASSERT_FALSE(rec.seq.empty());
    const std::uint64_t spanned = rec.seq.back() - rec.seq.front() + 1;
    EXPECT_GE(spanned, 101u);
    EXPECT_GE(rec.size() + 1, spanned);
    // The paper's gyro at rest after the warm-up stays within a few counts of Table 1's C1 + C2 = 508.
    for (std::size_t i = 0; i < rec.size(); ++i) EXPECT_NEAR(rec.counts[0][i], 506.0, 6.0) << "row " << i;
}

// Polls at the recorder's clock against a board paced 20 times faster: outputs 0.1 s apart, rows 2 s apart on the
// board's clock, each one output's window. `gap` had refused the log (metadata 'sample_period_s' is 0.1 s, but the
// rows are 2 s apart); it keeps both periods and calibrates the gyro's white noise to the paper model's 1.0239
// counts: 220 rows know the short-lag spread to 1/sqrt(440) = 4.8 %, 25 % is over 5 sigma.
TEST(RecordPty, GapReadsAPolledRecordingOfABoardPacedFasterThanTheRecorder) {
    TempDir dir("hilpoll");
    const auto [hil, path] = serve_hil_pty({"--speed", "20", "--duration", "500"}, dir.file("hil.out"));
    ASSERT_FALSE(path.empty()) << read_text(dir.file("hil.out"));
    const std::string log = dir.file("rec.csv");
    const RunResult r = record_then_end_hil(
        {"record", "--port", path, "--poll", "0.1", "--duration", "440", "-q", "-o", log}, hil, dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    ASSERT_EQ(host::read_log(log).metadata.get_double("sample_period_s"), 0.1);

    const RunResult gap = run_driftlab({"gap", log, "--replicates", "16", "--json"}, dir.path());
    ASSERT_EQ(gap.exit_code, 0) << gap.output;
    const auto j = nlohmann::json::parse(gap.output);
    EXPECT_NEAR(j["calibration"]["sample_period_s"].get<double>(), 2.0, 0.1);
    EXPECT_NEAR(j["calibration"]["outputs_per_row"].get<double>(), 20.0, 1.0);
    EXPECT_NEAR(j["calibration"]["channels"]["gyro"]["sigma_n_counts"].get<double>() / 1.0239, 1.0, 0.25);
}

// The port is the recording's alone (docs/security.md): a second recorder started on it is refused, naming the first
// by its process id, and the first records on to a whole log.
TEST(RecordPty, ASecondProgramCannotOpenThePortDuringARecording) {
    TempDir dir("exclusive");
    BoardThread board(paced_board(4.0, 120.0));
    const std::string log = dir.file("rec.csv");
    const pid_t first = spawn_driftlab(
        {"record", "--port", board.path(), "--stream", "0.1", "--duration", "20", "-o", log}, dir.file("first.out"));
    // The recording holds the port once its log has begun.
    for (int i = 0; i < 200 && !std::filesystem::exists(log); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    ASSERT_TRUE(std::filesystem::exists(log)) << read_text(dir.file("first.out"));
    const RunResult second = run_driftlab(
        {"record", "--port", board.path(), "--stream", "0.1", "--duration", "1", "-o", dir.file("second.csv")},
        dir.path());
    EXPECT_EQ(second.exit_code, 4) << second.output;
    // The holders are named: the first recorder (and the board's own end, which this test process keeps open).
    EXPECT_NE(second.output.find("in use by another program: "), std::string::npos) << second.output;
    EXPECT_NE(second.output.find("PID " + std::to_string(first) + " ("), std::string::npos) << second.output;
    const RunResult r = wait_child(first, dir.file("first.out"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_GT(host::read_log(log).size(), 150u);
}

// A full disk, as a file-size limit (prlimit --fsize, which the recorder meets as EFBIG): the recording ends with
// exit 4, its log is cut back to its last whole line and reads as it is, and the capture rebuilds the log of which
// the recorded one is the beginning (docs/recording.md "Durability").
TEST(RecordPty, AFullDiskEndsTheRecordingWithExit4AWholeLogAndACaptureThatRebuildsIt) {
    if (!std::filesystem::exists("/usr/bin/prlimit")) GTEST_SKIP() << "prlimit (util-linux) is not installed";
    TempDir dir("fulldisk");
    BoardThread board(paced_board(4.0, 120.0));
    const std::string log = dir.file("rec.csv");
    const pid_t pid = spawn_program("/usr/bin/prlimit",
                                    {"--fsize=20000", DRIFTLAB_BIN, "record", "--port", board.path(), "--stream", "0.1",
                                     "--duration", "60", "-o", log},
                                    dir.file("rec.out"));
    const RunResult r = wait_child(pid, dir.file("rec.out"));
    EXPECT_EQ(r.exit_code, 4) << r.output;
    EXPECT_NE(r.output.find("File too large"), std::string::npos) << r.output;
    const host::LogData rec = host::read_log(log);  // whole: no cut line to drop
    ASSERT_GT(rec.size(), 50u);
    const RunResult d = run_driftlab({"decode", log + ".cap", "-o", dir.file("rebuilt.csv")}, dir.path());
    ASSERT_EQ(d.exit_code, 0) << d.output;
    const std::string recorded = read_text(log), rebuilt = read_text(dir.file("rebuilt.csv"));
    EXPECT_GE(rebuilt.size(), recorded.size());
    EXPECT_EQ(rebuilt.compare(0, recorded.size(), recorded), 0);
}
