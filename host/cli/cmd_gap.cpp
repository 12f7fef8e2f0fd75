// `driftlab gap REAL.csv`: where the calibrated simulator differs from a real log, which effect explains it and
// how far the gap shrinks once that effect is added (host/gap, docs/gap.md).
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "driftlab/proto/messages.hpp"
#include "host/cli/commands.hpp"
#include "host/cli/gap_input.hpp"
#include "host/gap/calibrate.hpp"
#include "host/gap/diagnose.hpp"
#include "host/gap/diagnose_motion.hpp"
#include "host/gap/model_out.hpp"
#include "host/gap/verdict_stability.hpp"
#include "host/log/log_reader.hpp"
#include "host/util/error.hpp"
#include "host/util/output_file.hpp"
#include "host/util/output_folder.hpp"
#include "host/util/time_left.hpp"
#include "host/view/analysis_notes.hpp"
#include "host/view/gap_view.hpp"
#include "sim/model/model_file.hpp"

namespace driftlab::host::cli {
namespace {

struct GapCommandOptions {
    GapInput input;
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
};

// The outputs are checked before the diagnosis, which takes minutes: none may overwrite an input or another output.
void refuse_clashing_outputs(const GapCommandOptions& o) {
    // Only the forecast design splits the log at a fraction: interleaved tenths would silently ignore it.
    if (o.fit_fraction_given && o.holdout != gap::Holdout::forecast)
        throw UsageError(
            "--fit-fraction sets where --holdout forecast splits the log; the default interleaved design fits on "
            "tenths 0, 4, 5, 7, 9 of the log whatever the fraction: add --holdout forecast, or leave --fit-fraction "
            "out");
    if (!o.input.truth_path.empty() && o.stability > 0)
        throw UsageError("--stability simulates logs at rest from the estimated model; it does not take --truth");
    refuse_writing_over_input(o.model_out, "--model-out", o.input.path, "log");
    refuse_writing_over_input(o.model_out, "--model-out", o.input.model_path, "model file");
    refuse_file_on_output_folder(o.model_out, "--model-out", o.report_dir, "--report");
    if (!o.report_dir.empty())
        for (const std::string& file : view::report_files(o.report_dir)) {
            refuse_writing_over_input(file, "--report", o.input.path, "log");
            refuse_writing_over_input(file, "--report", o.input.model_path, "model file");
            refuse_two_outputs_in_one_file(o.model_out, "--model-out", file, "--report");
        }
}

// The diagnosis's options, with its progress on a terminal.
gap::GapOptions diagnosis_options(const GapCommandOptions& o) {
    gap::GapOptions options;
    options.replicates = o.replicates;
    options.seed = o.seed;
    options.fit_fraction = o.fit_fraction;
    options.holdout = o.holdout;
    options.explain = !o.locate_only;
    options.search_diffuse = o.search_diffuse;
    options.explain_options.max_effects = o.max_effects;
    options.channels = channels_named(o.input);
    if (::isatty(STDERR_FILENO) != 0)
        options.progress = [started = std::chrono::steady_clock::now()](const std::string& stage) {
            std::fprintf(stderr, "\r\033[Kgap: %.0f s, %s", seconds_since(started), stage.c_str());
        };
    return options;
}

// --model-out: the estimated model as a model file; returns the notes on what it could not hold.
std::vector<std::string> write_model_out(const GapCommandOptions& o, const gap::GapResult& r, const LogData& log,
                                         const gap::VerdictStability* stability) {
    const gap::ModelOut m = gap::model_out(r.whole_log_model, r.channels, gap::any_raw_codes(r), o.input.path);
    const std::string comment = view::model_file_comment(r, o.input.path + rows_used(o.input, log), m.notes, stability);
    write_output_file(o.model_out, sim::write_model(m.model, comment), "model file");
    return m.notes;
}

void run(const GapCommandOptions& o) {
    refuse_clashing_outputs(o);
    const auto [log, unit, notes, truth] = load_recording(o.input);
    for (const std::string& note : notes) view::print_note(note, o.json);
    // Only when the rows analysed reach it: --to before it loses nothing
    view::print_note(dropped_cut_line_note(log), o.json);
    if (!o.report_dir.empty()) make_output_folder(o.report_dir, "report");  // at once, not after the diagnosis
    if (!o.model_out.empty()) {
        check_output_file(o.model_out, "model file");
        // Refused now, not after the diagnosis
        gap::firmware_config(gap::smoothing_from_log(log), false, o.input.path);
    }
    const gap::GapOptions options = diagnosis_options(o);
    const gap::GapResult r =
        truth ? gap::diagnose_in_motion(log, *truth, unit, options) : gap::diagnose(log, unit, options);
    const gap::VerdictStability stability = gap::verdict_stability(r, log, unit, options, o.stability);
    if (options.progress) std::fprintf(stderr, "\r\033[K");
    const gap::VerdictStability* stable = stability.logs > 0 ? &stability : nullptr;
    if (!o.report_dir.empty()) view::write_gap_report(r, log, o.report_dir, options, stable);
    const std::vector<std::string> model_notes =
        o.model_out.empty() ? std::vector<std::string>{} : write_model_out(o, r, log, stable);
    if (o.json) {
        nlohmann::json j = view::gap_to_json(r, options);
        if (stable) j["stability"] = view::stability_to_json(stability);
        std::cout << j.dump(2) << "\n";
        for (const std::string& n : model_notes) std::fprintf(stderr, "driftlab gap: model file note: %s\n", n.c_str());
        return;
    }
    view::print_gap_text(r, options, log, stable);
    if (!o.report_dir.empty()) std::printf("report: %s/gap.md\n", o.report_dir.c_str());
    if (!o.model_out.empty())
        std::printf("model file: %s (driftlab hil --model %s simulates this unit)\n", o.model_out.c_str(),
                    o.model_out.c_str());
    for (const std::string& n : model_notes) std::printf("model file note: %s\n", n.c_str());
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
    cmd->add_option("file", o->input.path, "Real log: a canonical log, or a plain table with --tau0 and --as")
        ->required()
        ->check(non_empty_path());
    add_plain_recording_options(cmd, o->input);
    cmd->add_option("--model", o->input.model_path,
                    "Model file of the unit (front ends, converter) and its effects, part of the base: Gaussian "
                    "processes held at "
                    "the file's values, mean shapes refitted to the log; default: the paper's unit")
        ->check(non_empty_path());
    add_time_range_options(cmd, o->input.from_s, o->input.to_s);
    add_exclude_option(cmd, o->input.excluded,
                       "a shock or a bump in the middle of the log; the rows either side are joined");
    cmd->add_option(
           "--exclude-saturated", o->input.saturated_margin_s,
           "Leave out every stretch of rows whose sat_flags flag an analysed channel, with SECONDS more on either side "
           "(e.g. 0.5 for what a shock leaves after the rail), joined as with --exclude")
        ->check(non_negative_number());
    add_drop_cut_line_flag(cmd, o->input.drop_cut_line);
    cmd->add_option("--truth", o->input.truth_path,
                    "Ground truth of a log in motion (hil --trajectory writes LOG.truth.csv): its known input is "
                    "taken out first, and scale factor, cross-axis coupling and g-sensitivity join the candidates")
        ->check(non_empty_path());
    cmd->add_option("--channel", o->input.channels, "Channels to analyse (default: every channel that varies)")
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
