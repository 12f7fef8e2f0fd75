// `driftlab nav-eval`: navigation over many simulated runs with the firmware in the loop (native or the AVR binary
// in simavr): per seed a rest recording of the unit to fit its drift on, and a run along each trajectory from
// power-on with its ground truth; each scored as `nav` scores it, then summarised (host/nav/nav_eval, docs/nav.md
// §Monte Carlo).
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/cli/hil_run.hpp"
#include "host/cli/nav_eval_output.hpp"
#include "host/cli/shard_option.hpp"
#include "host/log/log_reader.hpp"
#include "host/log/truth_file.hpp"
#include "host/nav/effect_noise.hpp"
#include "host/nav/nav_eval.hpp"
#include "host/nav/nav_parts.hpp"
#include "host/nav/navigate.hpp"
#include "host/nav/unit_drift.hpp"
#include "host/util/error.hpp"
#include "host/util/input_file.hpp"
#include "host/util/output_folder.hpp"
#include "host/util/part_file.hpp"
#include "host/util/progress_bar.hpp"
#include "host/view/json_out.hpp"
#include "host/view/nav_eval_view.hpp"
#include "sim/model/model_file.hpp"
#include "sim/motion/truth_table.hpp"

namespace driftlab::host::cli {
namespace {

struct NavEvalOptions {
    int runs = 10;
    std::uint64_t seed = 1;
    std::vector<std::string> trajectories = {"stop-and-go"};
    double duration_s = 1810.0;
    double period_s = 0.1;
    double rest_before_s = 10.0;
    double fit_duration_s = 1800.0;
    std::string model_file;
    std::string target = "native";
    std::vector<std::string> aids = {"zupt"};
    bool effects_noise = false;
    nav::NavOptions nav;
    std::string work_dir;
    bool json = false;
    std::string plot_dir;
    std::pair<std::size_t, std::size_t> shard{0, 1};  // K, N
    std::string part;                                 // -o: this shard's part file
};

// Every option that shapes the runs, as a part states the campaign (the model file by its text: a part made from
// another file of the same name is of another campaign).
nlohmann::json campaign_json(const NavEvalOptions& o) {
    std::string model;
    if (!o.model_file.empty()) model = read_small_file(o.model_file, kMaxJsonFileBytes);
    return {{"runs", o.runs},
            {"seed", o.seed},
            {"trajectories", o.trajectories},
            {"duration_s", o.duration_s},
            {"period_s", o.period_s},
            {"rest_before_s", o.rest_before_s},
            {"fit_duration_s", o.fit_duration_s},
            {"model", model},
            {"target", o.target},
            {"aids", o.aids},
            {"effects_noise", o.effects_noise}};
}

// The canonical log `path` of the unit, simulated as `hil` would: at rest, or along `trajectory`.
void simulate(const NavEvalOptions& o, const std::string& trajectory, double duration_s, std::uint64_t seed,
              const std::string& path) {
    HilCliOptions h;
    h.duration_s = duration_s;
    h.period_s = o.period_s;
    h.model_file = o.model_file;
    h.seed = seed;
    h.target = o.target;
    h.trajectory = trajectory;
    if (!trajectory.empty()) h.rest_before_s = o.rest_before_s;
    sim::HilOptions run = build_options(h);
    write_hil_log(h, run, path);
}

// What every run of the campaign shares: the unit simulated and the navigation's options (with the bias processes of
// its effects when --effects-noise), read and derived once.
struct Campaign {
    sim::SimModel unit;
    nav::NavOptions options;
};

Campaign campaign(const NavEvalOptions& o) {
    Campaign c{o.model_file.empty() ? sim::paper_model() : sim::load_model_file(o.model_file), o.nav};
    if (o.effects_noise) {
        const nav::EffectNoise e = nav::effect_noise(c.unit);
        c.options.effects_bias_psd = e.bias_walk_psd;
        c.options.effects_used = e.used;
    }
    return c;
}

// Seed s: the unit's rest recording is simulated with seed 2s and its drift fitted once, for every trajectory of the
// seed; its runs are simulated with 2s + 1, so that no two logs share their noise.
nav::UnitDrift unit_drift_of_seed(const NavEvalOptions& o, std::uint64_t seed, const std::string& dir) {
    const std::string rest = dir + "/s" + std::to_string(seed) + "_rest.csv";
    simulate(o, "", o.fit_duration_s, 2 * seed, rest);
    return nav::fit_unit_drift(read_log(rest), -INFINITY, INFINITY);
}

nav::EvalRun evaluate_run(const NavEvalOptions& o, const Campaign& c, const nav::UnitDrift& drift,
                          const std::string& trajectory, std::uint64_t seed, const std::string& dir) {
    const std::string moving = dir + "/s" + std::to_string(seed) + "_" + trajectory + ".csv";
    simulate(o, trajectory, o.duration_s, 2 * seed + 1, moving);
    const LogData log = read_log(moving);
    const TruthFile truth = read_truth_file(sim::truth_path_for(moving));
    const nav::NavTruth nav_truth(truth, match_truth_rows(truth, log, false));
    nav::NavOptions options = c.options;
    options.aid.seed = seed;
    const nav::NavRun run = nav::navigate(log, c.unit, drift, nav_truth, options);
    return {trajectory, seed, nav::score(run, nav_truth)};
}

void run(NavEvalOptions& o) {
    for (const std::string& a : o.aids)
        if (!nav::enable_aid(o.nav.aid, a))
            throw UsageError("--aid: '" + a + "' is not an aid (zupt, odometry, fixes, none)");
    if (!o.plot_dir.empty()) make_output_folder(o.plot_dir, "plot");
    const bool keep = !o.work_dir.empty();
    const std::string dir =
        keep ? o.work_dir
             : (std::filesystem::temp_directory_path() / ("driftlab-nav-eval-" + std::to_string(getpid()))).string();
    make_output_folder(dir, "work");
    const auto progress = isatty(2) ? progress_bar() : std::function<void(double)>{};
    std::vector<nav::EvalRun> runs;
    const std::size_t seeds = static_cast<std::size_t>(o.runs);
    const std::size_t mine = seeds / o.shard.second + (o.shard.first < seeds % o.shard.second ? 1 : 0);
    const std::size_t total = o.trajectories.size() * mine;
    try {
        const Campaign c = campaign(o);
        for (int k = 0; k < o.runs; ++k) {
            // The shard's seeds: item k is shard k mod N's (nav_parts.hpp).
            if (static_cast<std::size_t>(k) % o.shard.second != o.shard.first) continue;
            const std::uint64_t seed = o.seed + static_cast<std::uint64_t>(k);
            const nav::UnitDrift drift = unit_drift_of_seed(o, seed, dir);
            for (const std::string& t : o.trajectories) {
                runs.push_back(evaluate_run(o, c, drift, t, seed, dir));
                if (progress) progress(static_cast<double>(runs.size()) / static_cast<double>(total));
            }
        }
    } catch (...) {
        if (!keep) std::filesystem::remove_all(dir);
        throw;
    }
    if (!keep) std::filesystem::remove_all(dir);
    if (o.part.empty()) {
        print_nav_eval(campaign_json(o), runs, o.json, o.plot_dir);
        return;
    }
    nav::write_nav_part({campaign_json(o), build_id(), o.shard.first, o.shard.second, seeds, std::move(runs)}, o.part);
    std::fprintf(stderr, "nav-eval: shard %zu/%zu: %zu of %zu runs in %s (driftlab merge PART... summarises them)\n",
                 o.shard.first, o.shard.second, total, seeds * o.trajectories.size(), o.part.c_str());
}

}  // namespace

void register_nav_eval(CLI::App& app) {
    auto o = std::make_shared<NavEvalOptions>();
    CLI::App* cmd = app.add_subcommand(
        "nav-eval", "Navigation over many simulated runs, the firmware in the loop: each variant's errors over time");
    cmd->add_option("--runs", o->runs, "Seeds per trajectory")
        ->capture_default_str()
        ->check(whole_number_in(1, 100000));
    cmd->add_option("--seed", o->seed, "First seed")->capture_default_str()->check(seed_number());
    cmd->add_option("--trajectories", o->trajectories, "Built-in trajectories or profile files, comma-separated")
        ->delimiter(',')
        ->capture_default_str();
    cmd->add_option("--duration", o->duration_s, "Each run's recording time [s]")
        ->capture_default_str()
        ->check(positive_number());
    cmd->add_option("--period", o->period_s, "Output period [s]")->capture_default_str()->check(positive_number());
    cmd->add_option("--rest-before", o->rest_before_s, "At rest this long before the trajectory starts [s]")
        ->capture_default_str()
        ->check(positive_number());
    cmd->add_option("--fit-duration", o->fit_duration_s, "The rest recording eq. 1 is fitted on [s from power-on]")
        ->capture_default_str()
        ->check(positive_number());
    cmd->add_option("--model", o->model_file, "Model file of the unit; default: the paper's")->check(non_empty_path());
    cmd->add_option("--target", o->target, "native, or avr (the firmware's ELF in simavr)")
        ->capture_default_str()
        ->check(CLI::IsMember({"native", "avr"}));
    cmd->add_option("--aid", o->aids, "Aids of the filter variants: zupt, odometry, fixes, comma-separated")
        ->delimiter(',')
        ->capture_default_str();
    cmd->add_flag("--effects-noise", o->effects_noise,
                  "The bias processes among --model's effects join the filters' process noise (what gap would find), "
                  "beside the Allan terms of the rest log");
    cmd->add_option("--work", o->work_dir, "Keep every run's logs and truths in this folder (default: a temporary one)")
        ->check(non_empty_path());
    cmd->add_flag("--json", o->json,
                  "Print JSON (keys: at_s, variants.<name>.{heading_error_deg,heading_error_deg_p95,position_error_m,"
                  "position_error_m_p95,nees_inside_fraction,...}, per_run)");
    cmd->add_option("--plot", o->plot_dir, "Write the errors against time into this folder")->check(non_empty_path());
    add_shard_options(cmd, o->shard, o->part, "seeds (each with every trajectory)")
        ->excludes("--json")
        ->excludes("--plot");
    cmd->callback([o] { run(*o); });
}

}  // namespace driftlab::host::cli
