// Recorder session: handshake, configuration, poll/stream loop, reconnect with back-off (recorder.hpp).
#include "host/io/recorder.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <optional>
#include <sstream>
#include <thread>

#include "host/io/board_client.hpp"
#include "host/io/capture.hpp"
#include "host/io/serial_port.hpp"
#include "host/util/error.hpp"
#include "host/util/output_file.hpp"
#include "host/util/output_folder.hpp"
#include "host/util/time_left.hpp"

namespace driftlab::host::io {
namespace {

using Clock = std::chrono::steady_clock;

constexpr auto kFlushInterval = std::chrono::milliseconds(1000);
constexpr auto kProgressInterval = std::chrono::milliseconds(250);
constexpr int kFirstBackoffMs = 250;
constexpr int kStreamPumpMs = 50;

// Handshake and configuration on an open link; empty string when the board is ready, else the problem.
std::string bring_up(BoardClient& client, const proto::ConfigPayload& config) {
    const HelloResult hello = client.hello();
    if (!hello.ok) return hello.problem;
    static_cast<void>(client.status());  // its uptime tells the log whether the firmware restarted
    const ConfigResult applied = client.configure(config);
    if (!applied.ok) return applied.problem;
    return {};
}

bool done(const AssemblyStats& s, double duration_s) {
    if (s.board_reconfigured()) return true;  // reconfigured by someone else: nothing more is this recording's
    return duration_s > 0.0 && s.first_t_s && s.last_t_s && *s.last_t_s - *s.first_t_s >= duration_s;
}

// The objects a recording session holds, for the steps that need them all.
struct Session {
    const RecordOptions& options;
    const std::atomic<bool>& stop;
    const RecordProgress& progress;
    SerialPort& port;
    BoardClient& client;
    LogAssembler& assembler;
    CaptureWriter& capture;
    Clock::time_point t0;  ///< when the board was up: the recording's wall time counts from here

    void event(const std::string& text) const { assembler.on_event(capture.write_event(text), text); }
};

// After the link was lost at `lost_at`: reopens the port and brings the board up again, with a doubling back-off,
// until it answers (true) or a stop is asked for (false); `attempts` counts the reopenings tried.
bool reconnect(const Session& s, Clock::time_point lost_at, int& attempts) {
    int backoff_ms = kFirstBackoffMs;
    while (!s.stop.load()) {
        // The wait in slices of the status cadence: the status line had stood still for a whole step (up to
        // 4 s), and a Ctrl-C had waited for its end.
        const auto attempt_at = Clock::now() + std::chrono::milliseconds(backoff_ms);
        for (auto now = Clock::now(); now < attempt_at && !s.stop.load(); now = Clock::now()) {
            const LinkLoss lost{seconds_since(lost_at), attempts + 1,
                                std::chrono::duration<double>(attempt_at - now).count()};
            if (s.progress) s.progress(s.assembler.stats(), seconds_since(s.t0), lost);
            std::this_thread::sleep_for(std::min<Clock::duration>(kProgressInterval, attempt_at - now));
        }
        if (s.stop.load()) return false;
        backoff_ms = std::min(backoff_ms * 2, s.options.reconnect_max_backoff_ms);
        ++attempts;
        if (!s.port.reopen()) continue;
        s.client.forget_partial_frame();
        const std::string again = bring_up(s.client, s.options.config);
        if (again.empty()) return true;
        s.capture.write_event("reconnect failed: " + again);
        s.event("lost");
        s.port.close();
    }
    return false;
}

// One step of a polled recording: a POLL when its time has come, then the link pumped until the next one is due.
LinkStatus poll_step(BoardClient& client, Clock::time_point& next_poll, std::chrono::milliseconds period) {
    LinkStatus link = LinkStatus::ok;
    const auto now = Clock::now();
    if (now >= next_poll) {
        link = client.send_poll();
        next_poll += period;
        if (next_poll < now) next_poll = now + period;  // fell behind (slow disk, suspend): no burst
    }
    if (link != LinkStatus::lost) {
        const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(next_poll - Clock::now());
        link = client.pump(static_cast<int>(std::clamp<std::int64_t>(wait.count(), 0, 100)));
    }
    return link;
}

// The poll or stream loop until the duration, a stop, or a link that does not come back; reconnects are counted in
// `summary`. Returns the board's refusal of a POLL, which ends a polled recording.
std::optional<std::string> run_session(Session& s, RecordSummary& summary) {
    const bool poll_mode = s.options.config.mode == static_cast<std::uint8_t>(proto::OutputMode::poll);
    const auto period = std::chrono::milliseconds(s.options.config.output_period_ms);
    auto next_poll = Clock::now();
    auto last_flush = s.t0;
    auto last_progress = s.t0;
    std::optional<std::string> refused;  // the board refused a POLL: its rows would not be the polled log asked for

    while (!s.stop.load() && !done(s.assembler.stats(), s.options.duration_s)) {
        LinkStatus link = LinkStatus::ok;
        if (poll_mode) {
            link = poll_step(s.client, next_poll, period);
            if ((refused = s.client.poll_refusal())) {
                s.capture.write_event(*refused);  // a note for whoever reads the capture
                break;
            }
        } else {
            link = s.client.pump(kStreamPumpMs);
        }

        if (link == LinkStatus::lost) {
            s.event("lost");
            const auto lost_at = Clock::now();
            const std::optional<double> last_t_s = s.assembler.stats().last_t_s;
            s.port.close();
            s.client.forget_partial_frame();
            int attempts = 0;
            const bool back = reconnect(s, lost_at, attempts);
            if (!back) break;
            ++summary.reconnects;
            // The row's t_s is board time and the rest host time: the line had given both as bare seconds.
            s.event("gap: " + link_lost_gap(last_t_s, std::chrono::duration<double>(lost_at - s.t0).count(),
                                            seconds_since(lost_at), attempts));
            s.event("resumed");
            next_poll = Clock::now();
        }

        const auto now = Clock::now();
        if (now - last_flush >= kFlushInterval) {
            // On the disk, not only with the OS: a power loss of the PC costs at most this second (docs/recording.md).
            s.assembler.sync();
            s.capture.sync();
            last_flush = now;
        }
        if (s.progress && now - last_progress >= kProgressInterval) {
            s.progress(s.assembler.stats(), seconds_since(s.t0), std::nullopt);
            last_progress = now;
        }
    }
    return refused;
}

}  // namespace

std::string utc_now_iso8601() {
    const auto now = std::chrono::system_clock::now();
    const std::time_t secs = std::chrono::system_clock::to_time_t(now);
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
    std::tm tm{};
    gmtime_r(&secs, &tm);
    char text[80];
    std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900, tm.tm_mon + 1,
                  tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, static_cast<int>(ms));
    return text;
}

RecordSummary record(const RecordOptions& options, const std::atomic<bool>& stop, const RecordProgress& progress) {
    const std::string capture_path =
        options.capture_path.empty() ? default_capture_path(options.log_path) : options.capture_path;
    // Before the port: opening it resets an Arduino, and a missing folder had been found only then (the capture's)
    // or after the handshake (the log's, with the capture left behind). Folders are made as `hil` makes its own.
    // An hour's recording is not made again by running the command once more from the shell's history.
    refuse_replacing(options.log_path, "log", "-o", options.overwrite);
    refuse_replacing(capture_path, "capture", "--capture", options.overwrite);
    NewFolders folders;  // removed again, when empty, if the run is refused before it writes
    folders.make_folder_of(options.log_path, "log");
    folders.make_folder_of(capture_path, "capture");
    check_output_file(options.log_path, "log");
    check_output_file(capture_path, "capture");
    SerialPort port(options.port, options.baud);

    const CaptureHeader header = {{"port", options.port},
                                  {"baud", std::to_string(options.baud)},
                                  {"start_utc", utc_now_iso8601()},
                                  {"recorder", options.recorder_name},
                                  {"capture", std::filesystem::path(capture_path).filename().string()}};
    auto capture = std::make_unique<CaptureWriter>(capture_path, header);
    LogAssembler assembler(options.log_path, header);
    BoardClient client(port);
    if (options.key) client.set_key(*options.key);
    client.set_tap([&](CaptureKind kind, const std::uint8_t* bytes, std::size_t n) {
        const std::uint64_t t_us = capture->write(kind, bytes, n);
        if (kind == CaptureKind::rx) assembler.on_rx(t_us, bytes, n);
    });
    if (const std::string problem = bring_up(client, options.config); !problem.empty()) {
        capture.reset();
        std::filesystem::remove(capture_path);
        throw DeviceError(options.port, problem);
    }
    Session session{options, stop, progress, port, client, assembler, *capture, {}};
    session.event("start");
    folders.keep();
    session.t0 = Clock::now();
    RecordSummary summary;
    const std::optional<std::string> refused = run_session(session, summary);
    summary.stopped_by_request = stop.load();
    session.event("stop");
    assembler.finish();
    if (refused) {
        throw DeviceError(options.port, *refused + " (" + options.log_path + " keeps the " +
                                            std::to_string(assembler.stats().rows) + " rows recorded before)");
    }
    summary.stats = assembler.stats();
    summary.polls_sent = client.counters().polls_sent;
    summary.wall_s = seconds_since(session.t0);
    if (progress) progress(summary.stats, summary.wall_s, std::nullopt);
    return summary;
}

}  // namespace driftlab::host::io
