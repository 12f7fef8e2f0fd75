// `driftlab record`: records a board over a serial or radio link into a canonical log plus its raw capture
// (host/io/recorder). Ctrl-C and SIGTERM stop it cleanly; the log is valid at every second anyway.
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "host/cli/commands.hpp"
#include "host/cli/stop_signals.hpp"
#include "host/io/key_file.hpp"
#include "host/io/recorder.hpp"
#include "host/io/status_line.hpp"
#include "host/util/error.hpp"
#include "sim/model/model_file.hpp"

namespace driftlab::host::cli {
namespace {

struct RecordCliOptions {
    std::string port;
    int baud = 115200;
    double poll_s = 0.0;
    double stream_s = 0.0;
    double duration_s = 0.0;
    int conversions = 25;
    int window = 25;
    int order = 0;
    bool raw = false;
    std::string output;
    std::string capture;
    bool quiet = false;
    bool overwrite = false;
    std::string key_file;
};

void run_record(const RecordCliOptions& o) {
    io::RecordOptions r;
    r.port = o.port;
    r.baud = o.baud;
    r.duration_s = o.duration_s;
    r.log_path = o.output;
    r.capture_path = o.capture;
    r.recorder_name = kProgramVersion;
    r.overwrite = o.overwrite;
    if (!o.key_file.empty()) r.key = io::read_key_file(o.key_file);
    const bool stream = o.stream_s > 0.0;
    r.config.output_period_ms =
        output_period_ms(stream ? o.stream_s : (o.poll_s > 0.0 ? o.poll_s : 0.1), stream ? "--stream" : "--poll");
    r.config.mode = static_cast<std::uint8_t>(stream ? proto::OutputMode::stream : proto::OutputMode::poll);
    r.config.conversions_per_output = static_cast<std::uint8_t>(o.conversions);
    r.config.window = static_cast<std::uint8_t>(o.window);
    r.config.fit_order = static_cast<std::uint8_t>(o.order);
    r.config.raw = o.raw ? 1 : 0;
    // The firmware's own check, before the port: a board's NAK had come back as a device error (exit 4) naming
    // only the field, e.g. --stream 0.01 with the default 25 conversions.
    if (const auto refusal = sim::firmware_refusal(r.config)) throw UsageError(refusal->field + ": " + refusal->reason);

    const std::atomic<bool>& stop = stop_on_signals();
    // An unplugged adapter or a closed pseudo-terminal may raise SIGHUP/SIGPIPE: that is a lost link, which
    // the recorder survives, not a reason to die.
    ::signal(SIGHUP, SIG_IGN);
    ::signal(SIGPIPE, SIG_IGN);
    // A file-size limit (ulimit -f) reached is a write the OS refused (EFBIG: exit 4, the log whole so far), not a
    // kill.
    ::signal(SIGXFSZ, SIG_IGN);

    const bool live = !o.quiet && ::isatty(STDERR_FILENO);
    io::RecordProgress progress;
    if (live) {
        progress = [](const io::AssemblyStats& s, double wall_s, const std::optional<io::LinkLoss>& lost) {
            std::fprintf(stderr, "\r%s\033[K", io::format_status_line(s, wall_s, lost).c_str());
            std::fflush(stderr);
        };
    }
    const io::RecordSummary sum = io::record(r, stop, progress);
    if (live) std::fprintf(stderr, "\n");

    const io::AssemblyStats& s = sum.stats;
    std::printf("recorded %llu rows", static_cast<unsigned long long>(s.rows));
    if (s.first_t_s) std::printf(" (t_s %.3f .. %.3f)", *s.first_t_s, *s.last_t_s);
    std::printf(" in %.1f s to %s\n", sum.wall_s, r.log_path.c_str());
    std::printf("frames %llu, lost %llu (%.3f %%), duplicate %llu, reordered %llu, polls %llu, reconnects %llu\n",
                static_cast<unsigned long long>(s.frames), static_cast<unsigned long long>(s.lost_frames),
                io::loss_percent(s), static_cast<unsigned long long>(s.duplicate_frames),
                static_cast<unsigned long long>(s.reordered_frames), static_cast<unsigned long long>(sum.polls_sent),
                static_cast<unsigned long long>(sum.reconnects));
    if (const std::string skipped = io::skipped_samples(s); !skipped.empty()) std::printf("%s\n", skipped.c_str());
    if (const std::string untrusted = io::untrusted_frames(s); !untrusted.empty())
        std::printf("%s\n", untrusted.c_str());
    if (s.board_reconfigured())
        throw BoardReconfigured(r.port + ": " +
                                (s.foreign_config_acks > 0
                                     ? "the board acknowledged a CONFIG_SET this recording did not send (another "
                                       "transmitter reconfigured it)"
                                     : "the board's outputs left the recording's window (it was reconfigured, its "
                                       "ACK lost, or it restarted)") +
                                ": recording stopped, " + r.log_path + " holds every row up to it");
}

}  // namespace

void register_record(CLI::App& app) {
    auto o = std::make_shared<RecordCliOptions>();
    CLI::App* cmd =
        app.add_subcommand("record", "Record a board over a serial/radio link into a log and a raw capture");
    cmd->add_option("--port", o->port, "Serial device (/dev/ttyUSB0, /dev/serial/by-id/..., /dev/pts/N)")
        ->required()
        ->check(non_empty_path());
    cmd->add_option("--baud", o->baud, "Baud rate [bit/s]")->capture_default_str()->check(baud_rate());
    auto* poll =
        cmd->add_option("--poll", o->poll_s, "Poll mode (the paper's), one POLL every PERIOD [s] (default 0.1)")
            ->check(positive_number());
    auto* stream = cmd->add_option("--stream", o->stream_s, "Stream mode: the board sends every PERIOD [s] unasked")
                       ->check(positive_number());
    poll->excludes(stream);
    cmd->add_option("--duration", o->duration_s, "Stop after this much board time [s] (default: until Ctrl-C)")
        ->check(non_negative_number());
    // The firmware's ranges, checked as hil checks them.
    cmd->add_option("--conversions", o->conversions, "ADC conversions per channel per output")
        ->capture_default_str()
        ->check(whole_number_in(1, proto::kConversionsPerOutputMax));
    cmd->add_option("--window", o->window, "Least-squares window N [conversions]")
        ->capture_default_str()
        ->check(whole_number_in(1, proto::kWindowMax));
    cmd->add_option("--order", o->order, "Least-squares order: 0 mean, 1 line")
        ->capture_default_str()
        ->check(whole_number_in(0, proto::kFitOrderMax));
    cmd->add_flag("--raw", o->raw, "Also record the raw ADC codes (RAW frames)");
    cmd->add_option("-o,--output", o->output, "Log file (canonical CSV)")->required()->check(non_empty_path());
    cmd->add_option("--capture", o->capture, "Raw capture file (default: LOG.cap beside the log)")
        ->check(non_empty_path());
    cmd->add_flag("-q,--quiet", o->quiet, "No live status line");
    cmd->add_flag("--overwrite", o->overwrite, "Replace a log or capture already there (refused otherwise)");
    cmd->add_option("--key", o->key_file,
                    "The board's command key (driftlab keygen; needed once `flash --key` gave it one)")
        ->check(non_empty_path());
    cmd->callback([o] { run_record(*o); });
}

}  // namespace driftlab::host::cli
