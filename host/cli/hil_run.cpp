// What `driftlab hil` is asked to run; see hil_run.hpp.
#include "host/cli/hil_run.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "host/cal/cal_file.hpp"
#include "host/cli/commands.hpp"
#include "host/io/hil_log.hpp"
#include "host/io/key_file.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/output_file.hpp"
#include "host/view/motion_view.hpp"
#include "sim/hil/eeprom_image.hpp"
#include "sim/hil/hil_preset.hpp"
#include "sim/model/drift.hpp"
#include "sim/model/model_file.hpp"
#include "sim/model/sensor.hpp"
#include "sim/motion/trajectories.hpp"
#include "sim/motion/truth_table.hpp"
#include "sim/sim_error.hpp"
#ifdef DRIFTLAB_HAVE_SIM_AVR
#include "sim/avr/avr_error.hpp"
#include "sim/avr/avr_hil.hpp"
#endif

namespace driftlab::host::cli {

#ifdef DRIFTLAB_HAVE_SIM_AVR
std::string firmware_elf(const HilCliOptions& o) { return o.elf.empty() ? sim::avr::default_elf_path() : o.elf; }

sim::avr::CycleBudget cycle_budget(const HilCliOptions& o, const sim::HilOptions& h) {
    const sim::KeyBytes key(h.key);
    return sim::avr::measure_cycle_budget(firmware_elf(o), h.model.firmware, 0.5, 5.0, true, h.eeprom, key.get());
}
#endif

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

namespace {

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

// --target: the native firmware core (the default) or the real ELF in simavr.
void set_target(const HilCliOptions& o, sim::HilOptions& h) {
    if (o.target == "avr") {
#ifdef DRIFTLAB_HAVE_SIM_AVR
        sim::avr::AvrBoardOptions avr{firmware_elf(o), o.gdb_port};
        avr.eeprom = h.eeprom;
        avr.die_temperature = h.die_temperature;
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
}

// The robot the unit rides (sim/motion): a built-in profile long enough for the run, or the user's file.
void set_trajectory(const HilCliOptions& o, sim::HilOptions& h) {
    if (o.trajectory.empty()) {
        if (o.rest_before_s) throw UsageError("--rest-before: needs --trajectory");
        if (!o.plot_dir.empty()) throw UsageError("--plot: needs --trajectory");
        return;
    }
    // The handshake takes a little board time before the recording: a minute more covers it.
    const double covered_s = h.duration_s + 60.0;
    try {
        h.trajectory = std::make_shared<const sim::Trajectory>(
            sim::make_trajectory(o.trajectory, covered_s, o.rest_before_s.value_or(0.0), o.seed));
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--trajectory: ") + e.what());
    }
}

}  // namespace

// The board's EEPROM at power-on: the calibration (--cal) and the key (--key) it keeps, as upload and flash leave them.
void set_eeprom(const HilCliOptions& o, sim::HilOptions& h) {
    if (o.cal_file.empty() && o.key_file.empty()) return;
    std::vector<proto::CalPayload> calibration;
    if (!o.cal_file.empty()) {
        const auto payloads = cal::to_payloads(cal::read_calibration(o.cal_file), o.cal_file);
        calibration.assign(payloads.begin(), payloads.end());
    }
    if (!o.key_file.empty()) h.key = io::read_key_file(o.key_file);
    h.eeprom = sim::eeprom_image(calibration, h.key);
}

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
    set_trajectory(o, h);
    set_eeprom(o, h);
    set_target(o, h);
    return h;
}

// The run's own metadata beside the board's: the effects the model file switches on, by name (their parameters are
// in the file), so that a log says what was simulated without the file beside it.
io::CaptureHeader run_metadata(const HilCliOptions& o, const sim::HilOptions& h, const std::string& effects) {
    io::CaptureHeader header = {{"seed", std::to_string(o.seed)},
                                {"effects", effects.empty() ? "none" : effects},
                                {"model", o.model_file.empty() ? "paper (built in)" : o.model_file},
                                {"model_name", h.model.name},
                                {"preset", o.preset},
                                {"target", o.target},
                                {"warm_up_s", format_double(h.warm_up_s)},
                                {"link_baud", format_double(h.model.link.baud)}};
    if (h.trajectory) {
        header.push_back({"trajectory", o.trajectory});
        header.push_back({"rest_before_s", format_double(o.rest_before_s.value_or(0.0))});
    }
    return header;
}

void write_motion_outputs(const HilCliOptions& o, const sim::HilOptions& h, const std::string& log_path,
                          const MotionRows& rows) {
    const std::string text = sim::truth_table(*h.trajectory, o.trajectory, o.rest_before_s.value_or(0.0), rows.t_s);
    write_output_file(sim::truth_path_for(log_path), text, "ground truth");
    if (o.plot_dir.empty()) return;
    const sim::ChannelModel& gyro = h.model.channels[channel_index(Channel::gyro)];
    const double per_dps =
        sim::FrontEnd(gyro.front_end, h.model.adc.vref_v).counts_per_unit(std::ldexp(1.0, h.model.adc.bits));
    const sim::Drift eq1(gyro.drift);
    std::vector<double> truth, measured;
    for (std::size_t k = 0; k < rows.t_s.size(); ++k) {
        truth.push_back(h.trajectory->input_at(rows.t_s[k]).yaw_rate_dps);
        measured.push_back((rows.gyro_counts[k] - eq1.at_counts(rows.t_s[k] + h.warm_up_s)) / per_dps);
    }
    view::write_yaw_rate_plot(o.plot_dir, rows.t_s, truth, measured);
}

std::string effect_names(const sim::HilOptions& h) {
    std::string effects;
    for (const sim::EffectSpec& e : h.model.effects) effects += (effects.empty() ? "" : ",") + e.name;
    return effects;
}

sim::HilSummary write_hil_log(const HilCliOptions& o, sim::HilOptions& h, const std::string& path) {
    io::HilLog log(path, run_metadata(o, h, effect_names(h)));
    h.on_ready = [&log](const proto::VersionPayload& v, const proto::ConfigPayload& c) { log.open(v, c); };
    MotionRows rows;  // where the ground truth is drawn
    const sim::HilSummary s = run_board(h, [&](const sim::HilRecord& r) {
        log.write(r);
        if (!h.trajectory) return;
        rows.t_s.push_back(r.t_s);
        rows.gyro_counts.push_back(r.value_counts[channel_index(Channel::gyro)]);
    });
    log.close();
    if (h.trajectory) write_motion_outputs(o, h, path, rows);
    return s;
}

}  // namespace driftlab::host::cli
