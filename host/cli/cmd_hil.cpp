// `driftlab hil`: host-in-the-loop simulation. The firmware core runs on an emulated board in virtual time, fed
// by the sensor model, talking through the link model to a host that writes the canonical log (sim/hil,
// docs/sim.md §Host-in-the-loop).
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "firmware/core/hal.hpp"
#include "host/cli/commands.hpp"
#include "host/cli/hil_run.hpp"
#include "host/cli/stop_signals.hpp"
#include "host/io/hil_log.hpp"
#include "host/io/pty_board.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/output_file.hpp"
#include "host/util/output_folder.hpp"
#include "host/util/progress_bar.hpp"
#include "host/util/time_left.hpp"
#include "host/view/hil_view.hpp"
#include "host/view/json_out.hpp"
#include "sim/hil/hil.hpp"
#include "sim/hil/hil_preset.hpp"
#include "sim/model/model_file.hpp"
#include "sim/model/sensor_model.hpp"
#include "sim/motion/trajectories.hpp"
#ifdef DRIFTLAB_HAVE_SIM_AVR
#include "sim/avr/avr_error.hpp"
#include "sim/avr/avr_hil.hpp"
#endif

namespace driftlab::host::cli {
namespace {

// --pty: the native board serves its UART on a pseudo-terminal, paced to the wall clock, until the duration
// (only when given) or Ctrl-C; a host such as `driftlab record --port PATH` configures and reads it
// (docs/recording.md "Recording a simulated board").
void serve_pty_command(const HilCliOptions& o, const sim::HilOptions& h) {
    if (o.target != "native") throw UsageError("--pty: only the native target is served on a pseudo-terminal");
    sim::SensorModel sensor(h.model, o.seed, h.warm_up_s);
    if (h.trajectory) {
        sensor.set_motion(sim::motion_source(h.trajectory));
        std::fprintf(stderr, "note: no ground truth is written with --pty (driftlab hil without --pty writes one)\n");
    }
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
    p.eeprom = h.eeprom;
    const auto code = [&sensor](Channel c, std::uint64_t tick) {
        return sensor.convert(c, static_cast<double>(tick) / fw::kTickHz).code;
    };
    const std::atomic<bool>& stop = stop_on_signals();
    // With --pty-link the link and the terminal it points to, "/tmp/imu -> /dev/pts/5": some tools refuse a symlink.
    const io::PtyBoardSummary s = io::serve_pty_board(p, code, stop, [&o](const std::string& path) {
        const std::string shown =
            o.pty_link.empty() ? path : path + " -> " + std::filesystem::read_symlink(path).string();
        std::printf("%s\n", shown.c_str());
        std::fflush(stdout);
    });
    std::fprintf(stderr, "served %.1f s of board time: %llu frames sent, %llu bytes nobody read\n", s.virtual_s,
                 static_cast<unsigned long long>(s.frames_sent), static_cast<unsigned long long>(s.bytes_dropped));
}

#ifdef DRIFTLAB_HAVE_SIM_AVR
nlohmann::json cycles_json(const sim::avr::CycleBudget& b) {
    nlohmann::json fns = nlohmann::json::object();
    for (const auto& f : b.functions)
        fns[f.label] = {{"calls", f.calls}, {"mean_cycles", f.mean_cycles()}, {"max_cycles", f.max_cycles}};
    return {{"measured", "a separate run of this configuration: " + kCycleRun},
            {"conversion_period_ticks", b.conversion_period_ticks},
            {"cpu_load", b.cpu_load},
            {"dropped", b.dropped},
            {"tx_overflow", b.tx_overflow},
            {"stack_high_water_bytes", b.stack_high_water_bytes},
            {"stack_budget_bytes", b.stack_budget_bytes},
            {"functions", fns}};
}
#endif

void run_hil_command(const HilCliOptions& o) {
    refuse_writing_over_input(o.output, "-o", o.model_file, "model file");
    sim::HilOptions h = build_options(o);
    if (o.pty) return serve_pty_command(o, h);
    const std::string path = o.output.empty() ? "out/" + o.preset + ".csv" : o.output;
    if (path == "-" && o.json) throw UsageError("--json: the log goes to standard output (-o -); write it to a file");
    if (path == "-" && h.trajectory)
        throw UsageError("--trajectory: the ground truth goes beside the log; write it to a file");
    if (path != "-") make_folder_of(path, "log");
    if (!o.plot_dir.empty()) make_output_folder(o.plot_dir, "plot");

    if (::isatty(STDERR_FILENO) && !o.json && path != "-") h.progress = progress_bar();

    // Under a debugger the stopped CPU waits inside the board's run, where no stop is looked at: Ctrl-C keeps its
    // default action there.
    if (o.gdb_port == 0) {
        h.stop = &stop_on_signals();
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
    const sim::HilSummary s = write_hil_log(o, h, path);
    const double wall_s = seconds_since(wall0);
    if (s.interrupted && h.progress) std::fprintf(stderr, "\n");
    const std::string interrupted = "interrupted after " + significant(s.simulated_s, 6) + " s of board time (" +
                                    significant(h.duration_s, 6) + " s asked for): " + path + " holds the " +
                                    std::to_string(s.host.rows) + " rows made so far";

    const view::HilRun run{path, o.preset, h.model.name, effect_names(h), o.seed, h.duration_s, wall_s, s};
    if (o.json) {
        nlohmann::json j = view::hil_json(run);
#ifdef DRIFTLAB_HAVE_SIM_AVR
        if (o.cycles && o.target == "avr" && !s.interrupted) j["avr_cycles"] = cycles_json(cycle_budget(o, h));
#endif
        j["interrupted"] = s.interrupted;
        view::write_json(std::cout, j);
        if (s.interrupted) throw Interrupted(interrupted);
        return;
    }
    // With the log on standard output (-o -), the summary goes beside it, not into it.
    std::ostream& out = path == "-" ? std::cerr : std::cout;
    view::print_hil_summary(out, run);
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
    cmd->add_option("--cal", opts->cal_file,
                    "Calibration (driftlab calibrate) in the board's EEPROM when it powers on, as an earlier "
                    "`driftlab upload` leaves it")
        ->check(non_empty_path());
    cmd->add_option("--key", opts->key_file,
                    "Command key (driftlab keygen) in the board's EEPROM when it powers on, as `driftlab flash --key` "
                    "leaves it; the host signs its commands with it")
        ->check(non_empty_path());
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
    cmd->add_option("--trajectory", opts->trajectory,
                    "The robot the unit rides: rest, square, figure8, stop-and-go, turntable, or a profile file "
                    "(docs/sim.md); writes LOG.truth.csv beside the log")
        ->check(non_empty_path());
    cmd->add_option("--rest-before", opts->rest_before_s, "--trajectory: at rest this long first [s]")
        ->check(non_negative_number());
    cmd->add_option("--plot", opts->plot_dir, "--trajectory: draw the truth's and the gyro's yaw rate in this folder")
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
