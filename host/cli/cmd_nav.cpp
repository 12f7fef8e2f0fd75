// `driftlab nav LOG`: planar navigation with the unit's drift model, four variants side by side (host/nav,
// docs/nav.md).
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/cli/gap_input.hpp"
#include "host/nav/effect_noise.hpp"
#include "host/nav/nav_score.hpp"
#include "host/nav/navigate.hpp"
#include "host/nav/unit_drift.hpp"
#include "host/util/error.hpp"
#include "host/util/output_file.hpp"
#include "host/util/output_folder.hpp"
#include "host/view/json_out.hpp"
#include "host/view/nav_view.hpp"
#include "sim/model/model_file.hpp"

namespace driftlab::host::cli {
namespace {

struct NavCommandOptions {
    GapInput input;
    bool at_rest = false;
    std::string drift_path;
    std::string fit_from;
    double fit_to_s = INFINITY;
    std::string effects_path;
    std::vector<std::string> aids;
    nav::NavOptions nav;
    bool json = false;
    std::string plot_dir;
    std::string output;
};

// --fit-from reads its recording as the log is read (a plain table through the same --as and --tau0), up to --fit-to.
std::optional<nav::UnitDrift> unit_drift(const NavCommandOptions& o) {
    if (!o.drift_path.empty() && !o.fit_from.empty()) throw UsageError("--drift and --fit-from: give one");
    if (!o.drift_path.empty()) return nav::read_unit_drift(o.drift_path);
    if (o.fit_from.empty()) return std::nullopt;
    GapInput rest = o.input;
    rest.path = o.fit_from;
    rest.truth_path.clear();
    rest.from_s = -INFINITY;
    rest.to_s = o.fit_to_s;
    return nav::fit_unit_drift(load_recording(rest).log, -INFINITY, INFINITY);
}

void set_aids(NavCommandOptions& o) {
    for (const std::string& a : o.aids)
        if (!nav::enable_aid(o.nav.aid, a))
            throw UsageError("--aid: '" + a + "' is not an aid (zupt, odometry, fixes, none)");
}

void run(NavCommandOptions& o) {
    set_aids(o);
    if (o.at_rest && !o.input.truth_path.empty()) throw UsageError("--truth and --at-rest: give one");
    if (!o.output.empty()) {
        refuse_writing_over_input(o.output, "-o", o.input.path, "log");
        check_output_file(o.output, "estimate");
    }
    if (!o.plot_dir.empty()) make_output_folder(o.plot_dir, "plot");
    o.input.motion_without_truth = true;
    const LoadedRecording rec = load_recording(o.input);
    std::optional<nav::NavTruth> truth;
    if (rec.truth)
        truth = nav::NavTruth(*rec.truth, match_truth_rows(*rec.truth, rec.log, o.input.windowed()));
    else if (o.at_rest)
        truth = nav::NavTruth();
    const std::optional<nav::UnitDrift> drift = unit_drift(o);
    if (!o.effects_path.empty()) {
        const nav::EffectNoise e = nav::effect_noise(sim::load_model_file(o.effects_path));
        if (e.used.empty())
            throw DataError(
                o.effects_path, 0,
                "no bias process among its effects (gauss_markov, rate_random_walk, flicker): nothing to add");
        o.nav.effects_bias_psd = e.bias_walk_psd;
        o.nav.effects_used = e.used + " (" + o.effects_path + ")";
    }
    const nav::NavRun run = nav::navigate(rec.log, rec.unit, drift, truth, o.nav);

    view::NavReport report{o.input.path,
                           drift ? drift->source : "",
                           o.aids,
                           rec.truth ? o.input.truth_path : (o.at_rest ? "at rest" : ""),
                           &run,
                           std::nullopt,
                           view::nav_curves(run, truth, view::kNavJsonPoints)};
    if (truth) report.score = nav::score(run, *truth);
    if (o.json)
        view::write_json(std::cout, view::nav_json(report));
    else
        view::print_nav_text(std::cout, report);
    if (!o.output.empty()) view::write_nav_estimate_csv(o.output, run);
    if (!o.plot_dir.empty()) view::write_nav_plots(o.plot_dir, view::nav_curves(run, truth, run.t_s.size()));
}

}  // namespace

void register_nav(CLI::App& app) {
    auto o = std::make_shared<NavCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "nav", "Navigate a log in the plane: dead reckoning and an EKF, with and without the unit's drift model");
    cmd->add_option("log", o->input.path,
                    "Canonical log of the unit riding the robot (hil --trajectory writes one), or a plain table with "
                    "--tau0 and --as")
        ->required()
        ->check(non_empty_path());
    add_plain_recording_options(cmd, o->input);
    cmd->add_option("--truth", o->input.truth_path, "Ground truth to score against (hil writes LOG.truth.csv)")
        ->check(non_empty_path());
    cmd->add_flag("--at-rest", o->at_rest, "Score against a unit at rest throughout (a static recording)");
    cmd->add_option("--drift", o->drift_path,
                    "The unit's eq. 1 (and noise): what fit --json or allan --json printed for a rest recording")
        ->check(non_empty_path());
    cmd->add_option("--fit-from", o->fit_from, "Fit eq. 1 and the Allan terms from this rest recording")
        ->check(non_empty_path());
    cmd->add_option("--fit-to", o->fit_to_s, "--fit-from: only its rows up to this time [s since power-on]")
        ->check(positive_number());
    cmd->add_option("--effects", o->effects_path,
                    "A model file of the effects gap found (gap --model-out): their bias processes join the filters' "
                    "process noise")
        ->check(non_empty_path());
    cmd->add_option("--model", o->input.model_path,
                    "Model file of the unit (front ends, converter); default: the paper's")
        ->check(non_empty_path());
    add_time_range_options(cmd, o->input.from_s, o->input.to_s);
    cmd->add_option("--aid", o->aids,
                    "Aids of the filter variants, comma-separated: zupt (zero velocity at detected stops), odometry "
                    "(wheel speed: the truth's, with noise), fixes (position: the truth's, with noise)")
        ->delimiter(',');
    cmd->add_option("--odometry-noise", o->nav.aid.odometry_sd_mps, "Wheel speed noise [m/s]")
        ->capture_default_str()
        ->check(positive_number());
    cmd->add_option("--fix-every", o->nav.aid.fix_every_s, "Seconds between position fixes")
        ->capture_default_str()
        ->check(positive_number());
    cmd->add_option("--fix-noise", o->nav.aid.fix_sd_m, "Position fix noise per axis [m]")
        ->capture_default_str()
        ->check(positive_number());
    cmd->add_option("--seed", o->nav.aid.seed, "Seed of the aids' noise")->capture_default_str()->check(seed_number());
    cmd->add_option("--rest", o->nav.rest_s, "The first seconds, where the unit stands (raw's bias)")
        ->capture_default_str()
        ->check(positive_number());
    cmd->add_option("--stop-window", o->nav.stop_window_s, "Quiet readings this long make a stop [s]")
        ->capture_default_str()
        ->check(positive_number());
    cmd->add_flag("--json", o->json,
                  "Print JSON (keys: at_s, variants.<name>.{heading_error_deg,position_error_m,nees_inside_fraction,"
                  "final,stops,...})");
    cmd->add_option("--plot", o->plot_dir, "Write heading, position error and trajectory plots into this folder")
        ->check(non_empty_path());
    cmd->add_option("-o,--output", o->output, "Write every variant's estimate as CSV (t_s, <variant>.x_m, ...)")
        ->check(non_empty_path());
    cmd->callback([o] { run(*o); });
}

}  // namespace driftlab::host::cli
