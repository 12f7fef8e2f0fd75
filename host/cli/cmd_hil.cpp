// `driftlab hil`: host-in-the-loop simulation. The firmware core runs on an emulated board in virtual time, fed
// by the sensor model, talking through the link model to a host that writes the canonical log (sim/hil,
// docs/sim.md §Host-in-the-loop).
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "firmware/core/hal.hpp"
#include "host/cli/commands.hpp"
#include "host/io/board_rows.hpp"
#include "host/io/log_assembler.hpp"
#include "host/io/pty_board.hpp"
#include "host/log/log_writer.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/output_file.hpp"
#include "host/util/output_folder.hpp"
#include "host/util/time_left.hpp"
#include "host/view/json_out.hpp"
#include "sim/hil/hil.hpp"
#include "sim/hil/hil_preset.hpp"
#include "sim/model/model_file.hpp"
#include "sim/model/sensor_model.hpp"
#ifdef DRIFTLAB_HAVE_SIM_AVR
#include "sim/avr/avr_error.hpp"
#include "sim/avr/avr_hil.hpp"
#endif

namespace driftlab::host::cli {
namespace {

struct HilCliOptions {
    std::string preset = "fig3";
    std::optional<double> duration_s;
    std::optional<double> period_s;
    std::optional<int> window;
    std::optional<int> conversions;
    std::optional<int> order;
    std::optional<double> warm_s;
    std::string model_file;
    std::uint64_t seed = 1;
    bool raw = false;
    bool stream = false;
    std::string output;
    bool json = false;
    std::string target = "native";  // native | avr (the real ELF in simavr, docs/avr-in-the-loop.md)
    std::string elf;                // AVR firmware; default: the one this build made
    int gdb_port = 0;               // > 0: simavr's gdb stub on this port, CPU stopped until avr-gdb continues
    bool cycles = false;            // AVR: also print the firmware's cycle budget at this configuration
    bool pty = false;               // serve the board on a pseudo-terminal instead of running a host
    std::optional<double> speed;    // --pty: virtual seconds per wall second (1 when not given)
    std::string pty_link;           // --pty: stable symlink to the pseudo-terminal
};

// Ctrl-C and SIGTERM end a run between events, so that the log keeps every row whole (a kill mid-write had cut the
// last one) and the summary says how far it got.
std::atomic<bool> g_stop{false};

void stop_on_signals() {
    std::signal(SIGINT, [](int) { g_stop.store(true); });
    std::signal(SIGTERM, [](int) { g_stop.store(true); });
}

// --pty: the native board serves its UART on a pseudo-terminal, paced to the wall clock, until the duration
// (only when given) or Ctrl-C; a host such as `driftlab record --port PATH` configures and reads it
// (docs/recording.md "Recording a simulated board").
void serve_pty_command(const HilCliOptions& o, const sim::HilOptions& h) {
    if (o.target != "native") throw UsageError("--pty: only the native target is served on a pseudo-terminal");
    sim::SensorModel sensor(h.model, o.seed, h.warm_up_s);
    const auto impaired = [](const sim::DirectionParams& d) {
        return d.latency_s > 0.0 || d.byte_error_rate > 0.0 || d.byte_drop_rate > 0.0 ||
               d.packet_loss.loss_in_good > 0.0 ||
               (d.packet_loss.p_good_to_bad > 0.0 && d.packet_loss.loss_in_bad > 0.0);
    };
    if (impaired(h.model.link.to_host) || impaired(h.model.link.to_firmware))
        std::fprintf(stderr,
                     "note: the model's [link] losses, errors and latency are not applied: the pseudo-terminal "
                     "carries the firmware's bytes as they are (driftlab hil without --pty simulates the link)\n");
    io::PtyBoardOptions p;
    p.speed = o.speed.value_or(1.0);
    p.duration_s = o.duration_s.value_or(0.0);
    p.link_path = o.pty_link;
    const auto code = [&sensor](Channel c, std::uint64_t tick) {
        return sensor.convert(c, static_cast<double>(tick) / fw::kTickHz).code;
    };
    stop_on_signals();
    // With --pty-link the link and the terminal it points to, "/tmp/imu -> /dev/pts/5": some tools refuse a symlink.
    const io::PtyBoardSummary s = io::serve_pty_board(p, code, g_stop, [&o](const std::string& path) {
        const std::string shown =
            o.pty_link.empty() ? path : path + " -> " + std::filesystem::read_symlink(path).string();
        std::printf("%s\n", shown.c_str());
        std::fflush(stdout);
    });
    std::fprintf(stderr, "served %.1f s of board time: %llu frames sent, %llu bytes nobody read\n", s.virtual_s,
                 static_cast<unsigned long long>(s.frames_sent), static_cast<unsigned long long>(s.bytes_dropped));
}

using MetadataPairs = std::vector<std::pair<std::string, std::string>>;

// One log line per record; the writer is opened once the handshake has produced VERSION for the metadata.
class HilLog {
public:
    HilLog(std::string path, MetadataPairs extra) : path_(std::move(path)), extra_(std::move(extra)) {}

    void open(const proto::VersionPayload& v, const proto::ConfigPayload& c) {
        raw_ = c.raw != 0;
        // hil's receiver leaves out a SAMPLE whose RAW was lost (MissingRaw::drop): no flags column.
        writer_ =
            std::make_unique<LogWriter>(path_, io::board_metadata("hil", v, c, extra_), io::board_columns(raw_, false));
    }
    void write(const sim::HilRecord& r) { writer_->write_row(io::board_log_row(r, raw_, false)); }
    void close() {
        if (writer_) writer_->close();
    }

private:
    std::string path_;
    MetadataPairs extra_;
    bool raw_ = false;
    std::unique_ptr<LogWriter> writer_;
};

nlohmann::json link_json(const sim::LinkCounters& c) {
    return {{"packets_sent", c.packets_sent},       {"packets_lost", c.packets_lost},
            {"packets_damaged", c.packets_damaged}, {"bytes_sent", c.bytes_sent},
            {"bytes_lost", c.bytes_lost},           {"bytes_dropped", c.bytes_dropped},
            {"bytes_corrupted", c.bytes_corrupted}, {"bytes_delivered", c.bytes_delivered}};
}

// A bar with the time left, since an AVR run in simavr can take minutes.
std::function<void(double)> progress_bar() {
    const auto started = std::chrono::steady_clock::now();
    return [started](double fraction) {
        const int width = 40;
        const int filled = static_cast<int>(fraction * width);
        std::fprintf(stderr, "\r[%s%s] %3d%%  %s\033[K", std::string(filled, '#').c_str(),
                     std::string(width - filled, ' ').c_str(), static_cast<int>(fraction * 100.0),
                     time_left(fraction, seconds_since(started)).c_str());
        if (fraction >= 1.0) std::fprintf(stderr, "\n");
    };
}

// Options that belong to another way of running are refused rather than silently ignored.
void check_option_combinations(const HilCliOptions& o) {
    if (!o.pty && (o.speed || !o.pty_link.empty()))
        throw UsageError(std::string(o.speed ? "--speed" : "--pty-link") + ": only with --pty");
    if (o.pty && (!o.output.empty() || o.json))
        throw UsageError(std::string(o.json ? "--json" : "-o") +
                         ": --pty serves the board and writes no log; the recorder does (driftlab record -o LOG)");
    // On a pseudo-terminal the recorder configures the board, as it does hardware: these had been ignored.
    if (o.pty && (o.period_s || o.window || o.conversions || o.order || o.raw || o.stream))
        throw UsageError(std::string(o.period_s      ? "--period"
                                     : o.window      ? "--window"
                                     : o.conversions ? "--conversions"
                                     : o.order       ? "--order"
                                     : o.raw         ? "--raw"
                                                     : "--stream") +
                         ": with --pty the recorder configures the board (driftlab record --poll/--stream, --window, "
                         "--conversions, --order, --raw)");
    if (o.target != "avr" && (!o.elf.empty() || o.gdb_port > 0 || o.cycles))
        throw UsageError(std::string(!o.elf.empty()   ? "--elf"
                                     : o.gdb_port > 0 ? "--gdb"
                                                      : "--cycles") +
                         ": only with --target avr");
}

// The command line's CONFIG fields over the model's.
void apply_firmware_options(const HilCliOptions& o, proto::ConfigPayload& fw) {
    if (o.period_s) fw.output_period_ms = output_period_ms(*o.period_s, "--period");
    if (o.window) fw.window = static_cast<std::uint8_t>(*o.window);
    if (o.conversions) fw.conversions_per_output = static_cast<std::uint8_t>(*o.conversions);
    if (o.order) fw.fit_order = static_cast<std::uint8_t>(*o.order);
    if (o.raw) fw.raw = 1;
    if (o.stream) fw.mode = static_cast<std::uint8_t>(proto::OutputMode::stream);
}

#ifdef DRIFTLAB_HAVE_SIM_AVR
std::string firmware_elf(const HilCliOptions& o) { return o.elf.empty() ? sim::avr::default_elf_path() : o.elf; }
#endif

sim::HilOptions build_options(const HilCliOptions& o) {
    check_option_combinations(o);
    const auto preset = sim::preset_from_name(o.preset);
    if (!preset) throw UsageError("--preset: expected fig3 or fig2, got '" + o.preset + "'");
    // The preset's and the options' CONFIG fields go over the model's, once; a file's get them before the
    // firmware's check of the joined fields, which then sees the configuration that will run.
    proto::ConfigPayload file_fw{};  // the file's own CONFIG, to tell whose figures a refusal is about
    const auto adjust = [&o, &preset, &file_fw](proto::ConfigPayload& fw) {
        file_fw = fw;
        sim::apply_preset_firmware(*preset, fw);
        apply_firmware_options(o, fw);
    };
    sim::HilOptions h;
    if (o.model_file.empty()) {
        h.model = sim::paper_model();
        adjust(h.model.firmware);
    } else {
        // With --pty the board boots with the firmware's defaults and the recorder's CONFIG replaces them: the
        // file's, the preset's and the options' fields never reach a firmware, which therefore has nothing to refuse.
        h.model = sim::load_model_file(o.model_file, {adjust, !o.pty});
    }
    h.seed = o.seed;
    sim::apply_preset_run(*preset, h);
    const proto::ConfigPayload& fw = h.model.firmware;
    if (const auto refusal = o.pty ? std::nullopt : sim::firmware_refusal(fw))
        throw UsageError(refusal->field + ": " + refusal->reason);
    // Unused there, but a [firmware] section the firmware would refuse is likely a mistake: say so rather than stop.
    if (const auto refusal = o.pty && !o.model_file.empty() ? sim::firmware_refusal(file_fw) : std::nullopt)
        std::fprintf(stderr,
                     "note: %s: [firmware] is not applied with --pty (the board starts with the firmware's "
                     "defaults and the recorder configures it); as written the firmware would refuse it: "
                     "%s: %s\n",
                     o.model_file.c_str(), refusal->field.c_str(), refusal->reason.c_str());
    // A model file's own period, raw flag and baud that its link cannot carry are its configuration's fault; a
    // period or raw flag from the command line (or the preset) is the command line's. A pseudo-terminal carries the
    // bytes as fast as they come (serve_pty_command): no baud rate is simulated there, so nothing to refuse.
    if (const auto refusal = o.pty ? std::nullopt : sim::link_capacity_refusal(h.model)) {
        const bool options_changed = fw.output_period_ms != file_fw.output_period_ms || fw.raw != file_fw.raw;
        if (!o.model_file.empty() && !options_changed) throw ConfigError(o.model_file, "link.baud", *refusal);
        throw UsageError(*refusal);
    }
    if (o.duration_s) h.duration_s = *o.duration_s;
    if (o.warm_s) h.warm_up_s = *o.warm_s;
    // A billion seconds (32 years of board time) is far beyond any run, and keeps the output count exact.
    if (h.duration_s > 1e9) {
        throw UsageError("--duration: at most 1e9 s, got " + significant(h.duration_s, 6));
    }
    // With --pty the output period is the recorder's, and --duration only bounds how long the board is served.
    if (!o.pty && h.duration_s < fw.output_period_ms / 1000.0)
        throw UsageError("--duration: shorter than one output period (" + std::to_string(fw.output_period_ms) + " ms)");
    if (o.target == "avr") {
#ifdef DRIFTLAB_HAVE_SIM_AVR
        sim::avr::AvrBoardOptions avr{firmware_elf(o), o.gdb_port};
        try {
            h.make_board = sim::avr::avr_board_factory(avr);
        } catch (const sim::avr::AvrError& e) {
            throw UsageError(std::string("--elf: ") + e.what());
        }
#else
        throw UsageError("--target avr: this driftlab was built without libsimavr-dev");
#endif
    } else if (o.target != "native") {
        throw UsageError("--target: expected native or avr, got '" + o.target + "'");
    }
    return h;
}

// The run; an emulated AVR that fails (the firmware crashed or stopped converting) is a device's failure.
sim::HilSummary run_board(const sim::HilOptions& h, const sim::RecordSink& on_record) {
#ifdef DRIFTLAB_HAVE_SIM_AVR
    try {
        return sim::run_hil(h, on_record);
    } catch (const sim::avr::AvrError& e) {
        throw DeviceError("--target avr", e.what());
    }
#else
    return sim::run_hil(h, on_record);
#endif
}

#ifdef DRIFTLAB_HAVE_SIM_AVR
// --cycles profiles every instruction, so it measures a short run of its own rather than the run the log came from.
const std::string kCycleRun = "5 s of streaming after 0.5 s (no POLL, so no receive interrupts)";

sim::avr::CycleBudget cycle_budget(const HilCliOptions& o, const sim::HilOptions& h) {
    return sim::avr::measure_cycle_budget(firmware_elf(o), h.model.firmware, 0.5, 5.0, true);
}
#endif

void run_hil_command(const HilCliOptions& o) {
    refuse_writing_over_input(o.output, "-o", o.model_file, "model file");
    sim::HilOptions h = build_options(o);
    if (o.pty) return serve_pty_command(o, h);
    const std::string path = o.output.empty() ? "out/" + o.preset + ".csv" : o.output;
    if (path == "-" && o.json) throw UsageError("--json: the log goes to standard output (-o -); write it to a file");
    if (path != "-") make_folder_of(path, "log");

    // The effects the model file switches on, by name (their parameters are in the file), so that a log says what
    // was simulated without the file beside it.
    std::string effects;
    for (const sim::EffectSpec& e : h.model.effects) effects += (effects.empty() ? "" : ",") + e.name;
    MetadataPairs extra = {{"seed", std::to_string(o.seed)},
                           {"effects", effects.empty() ? "none" : effects},
                           {"model", o.model_file.empty() ? "paper (built in)" : o.model_file},
                           {"model_name", h.model.name},
                           {"preset", o.preset},
                           {"target", o.target},
                           {"warm_up_s", format_double(h.warm_up_s)},
                           {"link_baud", format_double(h.model.link.baud)}};
    HilLog log(path, extra);
    h.on_ready = [&log](const proto::VersionPayload& v, const proto::ConfigPayload& c) { log.open(v, c); };
    if (::isatty(STDERR_FILENO) && !o.json && path != "-") h.progress = progress_bar();

    // Under a debugger the stopped CPU waits inside the board's run, where no stop is looked at: Ctrl-C keeps its
    // default action there.
    if (o.gdb_port == 0) {
        h.stop = &g_stop;
        stop_on_signals();
    }
#ifdef DRIFTLAB_HAVE_SIM_AVR
    // The CPU is stopped until a debugger continues it: say so, or the run looks hung.
    if (o.gdb_port > 0)
        std::fprintf(stderr,
                     "waiting for avr-gdb on port %d (the CPU is stopped until it continues): avr-gdb %s -ex "
                     "'target remote :%d'\n",
                     o.gdb_port, firmware_elf(o).c_str(), o.gdb_port);
#endif
    const auto wall0 = std::chrono::steady_clock::now();
    const sim::HilSummary s = run_board(h, [&log](const sim::HilRecord& r) { log.write(r); });
    const double wall_s = seconds_since(wall0);
    log.close();
    if (s.interrupted && h.progress) std::fprintf(stderr, "\n");
    const std::string interrupted = "interrupted after " + significant(s.simulated_s, 6) + " s of board time (" +
                                    significant(h.duration_s, 6) + " s asked for): " + path + " holds the " +
                                    std::to_string(s.host.rows) + " rows made so far";

    const double rtf = wall_s > 0.0 ? s.simulated_s / wall_s : 0.0;
    if (o.json) {
        nlohmann::json j = {{"log", path},
                            {"preset", o.preset},
                            {"model", h.model.name},
                            {"seed", o.seed},
                            {"duration_s", h.duration_s},
                            {"simulated_s", s.simulated_s},
                            {"wall_s", wall_s},
                            {"real_time_factor", rtf},
                            {"conversions", s.conversions},
                            {"frames_sent", s.to_host.packets_sent},
                            {"frames_received", s.host.frames_received},
                            {"frames_lost", s.host.frames_lost},
                            {"crc_errors", s.decoder.bad_crc},
                            {"bad_length", s.decoder.bad_length},
                            {"resync_bytes", s.decoder.resync_bytes},
                            {"polls_sent", s.host.polls_sent},
                            {"samples_received", s.host.samples_received},
                            {"rows", s.host.rows},
                            {"rows_missing_raw", s.host.rows_missing_raw},
                            {"empty_samples", s.host.empty_samples},
                            {"retries", s.host.retries},
                            {"link", {{"to_host", link_json(s.to_host)}, {"to_firmware", link_json(s.to_firmware)}}},
                            {"firmware",
                             {{"rx_frames", s.status.rx_frames},
                              {"rx_bad_crc", s.status.rx_bad_crc},
                              {"rx_bad_length", s.status.rx_bad_length},
                              {"rx_unknown_type", s.status.rx_unknown_type},
                              {"rx_resync_bytes", s.status.rx_resync_bytes},
                              {"rx_overflow", s.status.rx_overflow},
                              {"tx_overflow", s.status.tx_overflow},
                              {"dropped", s.status.dropped}}}};
#ifdef DRIFTLAB_HAVE_SIM_AVR
        if (o.cycles && o.target == "avr" && !s.interrupted) {
            const auto b = cycle_budget(o, h);
            nlohmann::json fns = nlohmann::json::object();
            for (const auto& f : b.functions)
                fns[f.label] = {{"calls", f.calls}, {"mean_cycles", f.mean_cycles()}, {"max_cycles", f.max_cycles}};
            j["avr_cycles"] = {{"measured", "a separate run of this configuration: " + kCycleRun},
                               {"conversion_period_ticks", b.conversion_period_ticks},
                               {"cpu_load", b.cpu_load},
                               {"dropped", b.dropped},
                               {"tx_overflow", b.tx_overflow},
                               {"stack_high_water_bytes", b.stack_high_water_bytes},
                               {"stack_budget_bytes", b.stack_budget_bytes},
                               {"functions", fns}};
        }
#endif
        j["interrupted"] = s.interrupted;
        view::write_json(std::cout, j);
        if (s.interrupted) throw Interrupted(interrupted);
        return;
    }
    // With the log on standard output (-o -), the summary goes beside it, not into it.
    std::ostream& out = path == "-" ? std::cerr : std::cout;
    // Every count that takes an output away from the log, so that outputs and rows add up from the text alone.
    if (!effects.empty()) out << "effects simulated: " << effects << "\n";
    out << "wrote " << s.host.rows << " rows to " << path;
    if (s.host.rows_missing_raw > 0)
        out << " (" << counted(s.host.rows_missing_raw, "sample") << " not logged: their RAW frame was lost)";
    if (s.host.empty_samples > 0)
        out << " (" << counted(s.host.empty_samples, "sample")
            << " not logged: n_window 0, no estimate behind their values)";
    out << "\n"
        << "frames: sent " << s.to_host.packets_sent << ", received " << s.host.frames_received << ", lost "
        << s.host.frames_lost << " (crc errors " << s.decoder.bad_crc << ")\n"
        << "link to host: " << s.to_host.packets_damaged << " frames damaged (" << s.to_host.packets_lost
        << " lost whole), " << s.to_host.bytes_dropped << " bytes dropped, " << s.to_host.bytes_corrupted
        << " corrupted; to firmware: " << s.to_firmware.packets_damaged << " frames damaged\n"
        << "simulated " << std::setprecision(6) << s.simulated_s << " s in " << std::setprecision(3) << wall_s
        << " s wall (" << std::lround(rtf) << "x real time)\n";
#ifdef DRIFTLAB_HAVE_SIM_AVR
    if (o.cycles && o.target == "avr" && !s.interrupted)
        out << "measured in a separate run of this configuration: " << kCycleRun << "\n"
            << sim::avr::format_cycle_budget(cycle_budget(o, h));
#endif
    if (s.interrupted) throw Interrupted(interrupted);
}

}  // namespace

void register_hil(CLI::App& app) {
    auto opts = std::make_shared<HilCliOptions>();
    CLI::App* cmd = app.add_subcommand(
        "hil", "Run the firmware in virtual time against the sensor and link models and write a canonical log");
    cmd->add_option("--preset", opts->preset,
                    "fig3 (4000 s from power-on at the model's output period) or fig2 (1000 outputs 0.1 s "
                    "apart, raw and least-squares)")
        ->capture_default_str();
    cmd->add_option("--duration", opts->duration_s, "Recording time after the handshake [s] (default: the preset's)")
        ->check(positive_number());
    cmd->add_option("--period", opts->period_s,
                    "Output (poll) period [s], whole milliseconds (default: the preset's, else the model's)")
        ->check(positive_number());
    cmd->add_option("--window", opts->window,
                    "Least-squares window N [conversions] (default: the preset's, else the model's)")
        ->check(whole_number_in(1, proto::kWindowMax));
    cmd->add_option("--conversions", opts->conversions,
                    "Conversions per channel per output (10 ms outputs need <= 12: docs/firmware.md; default: the "
                    "preset's, else the model's)")
        ->check(whole_number_in(1, proto::kConversionsPerOutputMax));
    cmd->add_option("--order", opts->order, "Least-squares fit order (default: the preset's, else the model's)")
        ->check(whole_number_in(0, proto::kFitOrderMax));
    cmd->add_option("--warm", opts->warm_s,
                    "The sensor was powered this long before the board booted [s] (default: the preset's)")
        ->check(non_negative_number());
    cmd->add_option("--model", opts->model_file, "Model file (TOML; default: the paper's unit, built in)")
        ->check(non_empty_path());
    cmd->add_option("--seed", opts->seed, "Seed of every random component")
        ->capture_default_str()
        ->check(seed_number());
    cmd->add_flag("--raw", opts->raw, "Also log the raw codes (RAW frames)");
    cmd->add_flag("--stream", opts->stream, "Stream mode: the firmware sends without being polled");
    cmd->add_option("-o,--output", opts->output, "Log file (default out/<preset>.csv; - for standard output)")
        ->check(non_empty_path());
    cmd->add_flag("--json", opts->json, "Print the run summary as JSON");
    cmd->add_flag("--pty", opts->pty,
                  "Serve the board's UART on a pseudo-terminal (prints its path) for "
                  "driftlab record; runs until --duration or Ctrl-C");
    cmd->add_option("--speed", opts->speed, "--pty: virtual seconds per wall second (default 1)")
        ->check(positive_number());
    cmd->add_option("--pty-link", opts->pty_link,
                    "--pty: also make this symlink to the pseudo-terminal (printed as PATH -> /dev/pts/N)")
        ->check(non_empty_path());
    cmd->add_option("--target", opts->target, "native (firmware core on the host) or avr (the real ELF in simavr)")
        ->capture_default_str();
    cmd->add_option("--elf", opts->elf, "AVR firmware ELF for --target avr (default: the one this build made)")
        ->check(non_empty_path());
    cmd->add_option("--gdb", opts->gdb_port,
                    "--target avr: start simavr's gdb stub on this TCP port and wait for "
                    "avr-gdb (docs/avr-in-the-loop.md)")
        ->check(whole_number_in(1, 65535));
    cmd->add_flag("--cycles", opts->cycles,
                  "--target avr: also print the firmware's cycle budget (ISR and fit "
                  "cycles, CPU load, stack) at this configuration");
    cmd->callback([opts] { run_hil_command(*opts); });
}

}  // namespace driftlab::host::cli
