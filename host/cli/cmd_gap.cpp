// `driftlab gap REAL.csv`: where the calibrated simulator differs from a real log, which effect explains it and
// how far the gap shrinks once that effect is added (host/gap, docs/gap.md).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "driftlab/proto/messages.hpp"
#include "host/cli/commands.hpp"
#include "host/fit/series.hpp"
#include "host/gap/calibrate.hpp"
#include "host/gap/candidates.hpp"
#include "host/gap/diagnose.hpp"
#include "host/gap/model_out.hpp"
#include "host/gap/plain_recording.hpp"
#include "host/gap/verdict_stability.hpp"
#include "host/log/log_reader.hpp"
#include "host/log/log_window.hpp"
#include "host/log/numeric_table.hpp"
#include "host/util/channel_name.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/output_file.hpp"
#include "host/util/output_folder.hpp"
#include "host/util/time_left.hpp"
#include "host/view/analysis_notes.hpp"
#include "host/view/gap_phrases.hpp"
#include "host/view/gap_view.hpp"
#include "sim/model/model_file.hpp"

namespace driftlab::host::cli {
namespace {

struct GapCommandOptions {
    std::string path;
    std::string model_path;
    std::vector<std::string> channels;
    bool json = false;
    std::string report_dir;
    std::string model_out;
    std::size_t stability = 0;
    int replicates = 40;
    std::uint64_t seed = 1;
    double fit_fraction = 0.6;
    bool fit_fraction_given = false;
    gap::Holdout holdout = gap::BatteryOptions{}.holdout;
    bool locate_only = false;
    bool search_diffuse = false;
    int max_effects = gap::ExplainOptions{}.max_effects;
    std::vector<std::string> mappings;  ///< plain recordings: CHANNEL=COLUMN:LSB
    double tau0_s = 0.0;                ///< plain recordings: the raw sample period
    std::size_t block = 1;              ///< plain recordings: samples averaged per output
    double from_s = -INFINITY;          ///< rows kept: from_s <= t_s <= to_s
    double to_s = INFINITY;
    std::vector<TimeWindow> excluded;  ///< --exclude: stretches left out
    double saturated_margin_s = -1.0;  ///< --exclude-saturated: seconds either side of each saturated stretch; < 0: off
    bool drop_cut_line = false;        ///< canonical logs: a cut last line is dropped (and noted), not refused

    bool windowed() const { return from_s != -INFINITY || to_s != INFINITY; }
};

struct Loaded {
    LogData log;
    sim::SimModel unit;
    std::vector<std::string> notes;  ///< what --from/--to kept (--exclude's windows are the result's left_out)
};

// --channel: the channels named (none named: all false, which selects every one).
std::array<bool, kChannelCount> channels_named(const GapCommandOptions& o) {
    std::array<bool, kChannelCount> out{};
    for (const std::string& name : o.channels) {
        const std::optional<Channel> c = channel_named(name);
        if (!c) throw UsageError("--channel: unknown channel '" + name + "' (" + channel_name_list() + ")");
        out[channel_index(*c)] = true;
    }
    return out;
}

// Cuts `log` to the rows --from/--to keep (all without them), less those --exclude and --exclude-saturated leave out,
// and returns the note of what the range kept. Only the channels the diagnosis analyses count as saturated: a channel
// stuck at a rail is left out of it, not its rows.
std::vector<std::string> cut_to_window(const GapCommandOptions& o, LogData& log) {
    std::vector<std::string> notes = fit::selection_notes(log.t_s, o.from_s, o.to_s, {});
    if (o.windowed()) log = rows_between(log, o.from_s, o.to_s);
    std::vector<TimeWindow> windows = o.excluded;
    if (o.saturated_margin_s >= 0.0) {
        gap::GapOptions selection;
        selection.channels = channels_named(o);
        const auto saturated = saturated_stretches(log, gap::analysed_channels(log, selection), o.saturated_margin_s);
        windows.insert(windows.end(), saturated.begin(), saturated.end());
    }
    if (!windows.empty()) log = rows_outside(log, windows);
    return notes;
}

// A canonical log the simulator can stand beside: its converter, and the smoothing the replicates must repeat (a
// window of 1 assumed for a missing one makes every averaged log look broken).
LogData read_canonical(std::istream& in, const std::string& path, ReadOptions options, const sim::SimModel& unit) {
    options.assumed_adc_bits = unit.adc.bits;
    LogData log = parse_log(in, path, options);
    if (const auto bits = log.metadata.get_int("adc_bits"); bits && *bits != unit.adc.bits)
        throw DataError(path, log.metadata.line_of("adc_bits"),
                        "adc_bits is " + std::to_string(*bits) + ", but the simulator's converter has " +
                            std::to_string(unit.adc.bits) + " bits");
    std::string missing;
    for (const char* key : {"window", "fit_order", "conversions_per_output"})
        if (!log.metadata.has(key)) missing += std::string(missing.empty() ? "" : ", ") + "'" + key + "'";
    if (!missing.empty())
        throw DataError(
            path, 0,
            "the metadata lacks " + missing +
                ": gap repeats the firmware's smoothing in every replicate and "
                "needs all of 'window', 'fit_order' and 'conversions_per_output' (record, decode and hil write them)");
    return log;
}

// A canonical log as it is, with the unit of --model or the paper's; a plain table through its column mappings
// (never guessed), with a unit whose codes are the columns' LSBs (set by the whole table); then --from/--to and
// --exclude.
Loaded load(const GapCommandOptions& o) {
    const sim::SimModel unit = o.model_path.empty() ? sim::paper_model() : sim::load_model_file(o.model_path);
    fit::OpenedSource source = fit::open_source(o.path);
    const ReadOptions read = fit::cut_line_options(source, o.path, o.drop_cut_line);
    if (source.canonical_log) {
        if (!o.mappings.empty() || o.tau0_s > 0.0 || o.block != 1)
            throw UsageError("--as, --tau0 and --block are for plain recordings; " + o.path + " is a canonical log");
        Loaded out{read_canonical(source.in, o.path, read, unit), unit, {}};
        out.notes = cut_to_window(o, out.log);
        return out;
    }
    if (o.mappings.empty() || !(o.tau0_s > 0.0))
        throw UsageError(o.path +
                         " is not a canonical log: a plain recording needs --tau0 SECONDS and at least one "
                         "--as CHANNEL=COLUMN:LSB (e.g. --as gyro=col1:0.00875)");
    gap::PlainRecording how;
    for (const auto& m : o.mappings) how.columns.push_back(gap::parse_column_mapping(m));
    how.sample_period_s = o.tau0_s;
    how.block = o.block;
    Loaded out{gap::log_from_table(parse_numeric_table(source.in, o.path), how), unit, {}};
    out.unit = gap::unit_of_recording(unit, how, out.log);
    out.notes = cut_to_window(o, out.log);
    return out;
}

// " (rows from X s to Y s, without A s to B s)" where --from/--to, --exclude or --exclude-saturated chose them, else
// "".
std::string rows_used(const GapCommandOptions& o, const LogData& log) {
    if (!o.windowed() && log.cuts.empty()) return "";
    char text[80];
    // Rows remain, or it was refused
    std::snprintf(text, sizeof text, " (rows from %g s to %g s", log.t_s.front(), log.t_s.back());
    std::string out = text;
    for (std::size_t i = 0; i < log.cuts.size(); ++i) {
        std::snprintf(text, sizeof text, "%s%g s to %g s", i == 0 ? ", without " : " and ", log.cuts[i].from_s,
                      log.cuts[i].to_s);
        out += text;
    }
    return out + ")";
}

void run(const GapCommandOptions& o) {
    // Only the forecast design splits the log at a fraction: interleaved tenths would silently ignore it.
    if (o.fit_fraction_given && o.holdout != gap::Holdout::forecast)
        throw UsageError(
            "--fit-fraction sets where --holdout forecast splits the log; the default interleaved design fits on "
            "tenths 0, 4, 5, 7, 9 of the log whatever the fraction: add --holdout forecast, or leave --fit-fraction "
            "out");
    refuse_writing_over_input(o.model_out, "--model-out", o.path, "log");
    refuse_writing_over_input(o.model_out, "--model-out", o.model_path, "model file");
    refuse_file_on_output_folder(o.model_out, "--model-out", o.report_dir, "--report");
    if (!o.report_dir.empty())
        for (const std::string& file : view::report_files(o.report_dir)) {
            refuse_writing_over_input(file, "--report", o.path, "log");
            refuse_writing_over_input(file, "--report", o.model_path, "model file");
            refuse_two_outputs_in_one_file(o.model_out, "--model-out", file, "--report");
        }
    const auto [log, unit, notes] = load(o);
    for (const std::string& note : notes) view::print_note(note, o.json);
    // Only when the rows analysed reach it: --to before it loses nothing
    view::print_note(dropped_cut_line_note(log), o.json);
    if (!o.report_dir.empty()) make_output_folder(o.report_dir, "report");  // at once, not after the diagnosis
    if (!o.model_out.empty()) {
        check_output_file(o.model_out, "model file");
        gap::firmware_config(gap::smoothing_from_log(log), false, o.path);  // refused now, not after the diagnosis
    }
    gap::GapOptions options;
    options.replicates = o.replicates;
    options.seed = o.seed;
    options.fit_fraction = o.fit_fraction;
    options.holdout = o.holdout;
    options.explain = !o.locate_only;
    options.search_diffuse = o.search_diffuse;
    options.explain_options.max_effects = o.max_effects;
    const bool tty = ::isatty(STDERR_FILENO) != 0;
    const auto started = std::chrono::steady_clock::now();
    if (tty)
        options.progress = [started](const std::string& stage) {
            std::fprintf(stderr, "\r\033[Kgap: %.0f s, %s", seconds_since(started), stage.c_str());
        };
    options.channels = channels_named(o);
    const gap::GapResult r = gap::diagnose(log, unit, options);
    const gap::VerdictStability stability = gap::verdict_stability(r, log, unit, options, o.stability);
    if (tty) std::fprintf(stderr, "\r\033[K");
    if (!o.report_dir.empty())
        view::write_gap_report(r, log, o.report_dir, options, stability.logs > 0 ? &stability : nullptr);
    std::vector<std::string> model_notes;
    if (!o.model_out.empty()) {
        const gap::ModelOut m = gap::model_out(r.whole_log_model, r.channels, gap::any_raw_codes(r), o.path);
        std::string effects;
        for (const auto& e : r.accepted) effects += " " + e.effect + " (" + e.channel + ")";
        std::string comment = "driftlab gap " + o.path + rows_used(o, log) + ": verdict " + r.verdict +
                              "\ncalibrated eq. 1 and white noise of the analysed "
                              "channels, the log's smoothing, effects added:" +
                              (effects.empty() ? " none" : effects);
        if (const std::string given = view::given_effects_sentence(r.given); !given.empty()) comment += "\n" + given;
        for (const std::string& n : m.notes) comment += "\nnote: " + n;
        if (stability.logs > 0)
            for (const std::string& line : view::stability_text(stability, r.verdict)) comment += "\n" + line;
        write_output_file(o.model_out, sim::write_model(m.model, comment), "model file");
        model_notes = m.notes;
    }
    if (o.json) {
        nlohmann::json j = view::gap_to_json(r, options);
        if (stability.logs > 0) j["stability"] = view::stability_to_json(stability);
        std::cout << j.dump(2) << "\n";
        for (const std::string& n : model_notes) std::fprintf(stderr, "driftlab gap: model file note: %s\n", n.c_str());
    } else {
        view::print_gap_text(r, options, log, stability.logs > 0 ? &stability : nullptr);
        if (!o.report_dir.empty()) std::printf("report: %s/gap.md\n", o.report_dir.c_str());
        if (!o.model_out.empty())
            std::printf("model file: %s (driftlab hil --model %s simulates this unit)\n", o.model_out.c_str(),
                        o.model_out.c_str());
        for (const std::string& n : model_notes) std::printf("model file note: %s\n", n.c_str());
    }
}

}  // namespace

void add_holdout_option(CLI::App* cmd, gap::Holdout& holdout) {
    cmd->add_option_function<std::string>(
        "--holdout",
        [&holdout](const std::string& name) {
            const auto h = gap::holdout_from_name(name);
            if (!h) throw CLI::ValidationError("--holdout", "expected interleaved or forecast, got '" + name + "'");
            holdout = *h;
        },
        "Held-out design: interleaved (tenths 0, 4, 5, 7, 9 fit, the others judge; sees effects confined to the "
        "warm-up; default) or "
        "forecast (fit on the first part, judge on the rest)");
}

void register_gap(CLI::App& app) {
    auto o = std::make_shared<GapCommandOptions>();
    CLI::App* cmd = app.add_subcommand("gap",
                                       "Sim-to-real gap: where the calibrated simulator differs from a real log, "
                                       "which effect explains it, how far the gap shrinks");
    cmd->add_option("file", o->path, "Real log: a canonical log, or a plain table with --tau0 and --as")
        ->required()
        ->check(non_empty_path());
    cmd->add_option(
        "--as", o->mappings,
        "Plain recordings: analyse COLUMN (its name, or col1... without a name line) as CHANNEL, in codes of "
        "LSB (its resolution in the column's unit: deg/s or g unless UNIT is mdps, rad/s, mg or m/s2), "
        "e.g. gyro=col1:0.00875 or gyro=gx:1.33e-4:rad/s; repeat per channel");
    cmd->add_option("--tau0", o->tau0_s,
                    "Plain recordings: the raw sample period [s] (timing from a time column, as fit finds it, "
                    "if there is one)")
        ->check(positive_number());
    cmd->add_option("--block", o->block,
                    "Plain recordings: samples averaged per output (an order-0 smoother of that "
                    "window; default 1)")
        ->check(whole_number_in(1, proto::kConversionsPerOutputMax));
    cmd->add_option("--model", o->model_path,
                    "Model file of the unit (front ends, converter) and its effects, part of the base: Gaussian "
                    "processes held at "
                    "the file's values, mean shapes refitted to the log; default: the paper's unit")
        ->check(non_empty_path());
    add_time_range_options(cmd, o->from_s, o->to_s);
    add_exclude_option(cmd, o->excluded, "a shock or a bump in the middle of the log; the rows either side are joined");
    cmd->add_option(
           "--exclude-saturated", o->saturated_margin_s,
           "Leave out every stretch of rows whose sat_flags flag an analysed channel, with SECONDS more on either side "
           "(e.g. 0.5 for what a shock leaves after the rail), joined as with --exclude")
        ->check(non_negative_number());
    add_drop_cut_line_flag(cmd, o->drop_cut_line);
    cmd->add_option("--channel", o->channels, "Channels to analyse (default: every channel that varies)")
        ->delimiter(',');
    cmd->add_option("--replicates", o->replicates, "Simulated replicates R (>= 10)")
        ->check(whole_number_in(10, 100000));
    cmd->add_option("--seed", o->seed, "Seed of the replicates (common random numbers)")->check(seed_number());
    const CLI::Option* fit_fraction =
        cmd->add_option("--fit-fraction", o->fit_fraction,
                        "With --holdout forecast: the first part of the log (by time) used to fit "
                        "candidates (default 0.6; refused with the interleaved design, which "
                        "does not split at a fraction)")
            ->check(number_in(0.3, 0.85));
    add_holdout_option(cmd, o->holdout);
    cmd->add_flag("--locate-only", o->locate_only, "Only locate the gap; do not fit candidate effects");
    cmd->add_flag("--search-diffuse", o->search_diffuse,
                  "Also fit candidates when no cell is located but the held-out gap score exceeds its bound (a diffuse "
                  "gap); off by default, as gap-eval scores it");
    cmd->add_option("--max-effects", o->max_effects,
                    "Effects added stepwise at most (default 3); 1 stops after the first, for a log known to lack one "
                    "effect: later steps can add a wrong second effect beside the right one (docs/gap.md)")
        ->check(whole_number_in(1, gap::ExplainOptions{}.max_effects));
    std::string keys;
    for (const char* k : view::kGapJsonKeys) keys += (keys.empty() ? "" : ", ") + std::string(k);
    cmd->add_flag("--json", o->json, "Print JSON (keys: " + keys + "; stability with --stability)");
    cmd->add_option("--report", o->report_dir, "Write gap.md with plots into this folder")->check(non_empty_path());
    cmd->add_option("--stability", o->stability,
                    "Diagnose N logs simulated from the estimated model, as the log was, and say how many get its "
                    "verdict (repeatability, not correctness) "
                    "and how the added effects' estimates scatter over them (N times the diagnosis's time)")
        ->check(whole_number_in(0, 1000));
    cmd->add_option("--model-out", o->model_out,
                    "Write the estimated model (calibrated base and the effects added, estimated on the whole log) as "
                    "a model file "
                    "for driftlab hil --model and gap --model")
        ->check(non_empty_path());
    cmd->callback([o, fit_fraction] {
        o->fit_fraction_given = fit_fraction->count() > 0;
        run(*o);
    });
}

}  // namespace driftlab::host::cli
