// `driftlab fleet LOG... | DIR`: a batch of boards characterised from their logs — each board's eq. 1 fit, noise
// terms and gap verdict, the batch's distributions and the boards that stand out (host/fleet, docs/fleet.md);
// resumable through a cache, and in shards for a cluster (docs/cluster.md).
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include "host/cli/commands.hpp"
#include "host/cli/fleet_output.hpp"
#include "host/cli/shard_option.hpp"
#include "host/fleet/board_cache.hpp"
#include "host/fleet/fleet_parts.hpp"
#include "host/fleet/fleet_run.hpp"
#include "host/util/channel_name.hpp"
#include "host/util/error.hpp"
#include "host/util/output_folder.hpp"
#include "host/util/part_file.hpp"
#include "host/util/time_left.hpp"

namespace driftlab::host::cli {
namespace {

struct FleetCommandOptions {
    std::vector<std::string> inputs;
    fleet::FleetOptions fleet;
    bool no_gap = false;
    std::string cache_dir;
    bool no_cache = false;
    std::pair<std::size_t, std::size_t> shard{0, 1};  // K, N
    std::string part;
    bool json = false;
    std::string plot_dir, report_dir;
};

fleet::FleetProgress progress_on_terminal() {
    if (::isatty(STDERR_FILENO) == 0) return {};
    return [started = std::chrono::steady_clock::now()](std::size_t done, std::size_t total, const std::string& log) {
        std::fprintf(stderr, "\r\033[Kfleet: %.0f s, board %zu of %zu: %s", seconds_since(started), done + 1, total,
                     log.c_str());
    };
}

void run(FleetCommandOptions& o) {
    for (const std::string& name : o.fleet.board.channels)
        if (!channel_named(name))
            throw UsageError("--channel: unknown channel '" + name + "' (" + channel_name_list() + ")");
    o.fleet.board.gap = !o.no_gap;
    o.fleet.cache_dir = o.no_cache ? "" : (o.cache_dir.empty() ? fleet::default_cache_dir() : o.cache_dir);
    if (!o.plot_dir.empty()) make_output_folder(o.plot_dir, "plot");
    if (!o.report_dir.empty()) make_output_folder(o.report_dir, "report");
    const std::vector<std::string> logs = fleet::fleet_logs(o.inputs);
    const fleet::FleetProgress progress = progress_on_terminal();
    fleet::FleetRun r = fleet::run_fleet(logs, o.fleet, o.shard.first, o.shard.second, progress);
    if (progress) std::fprintf(stderr, "\r\033[K");
    if (r.from_cache > 0)
        std::fprintf(stderr, "fleet: %zu of %zu boards read back from %s (analysed before with these options)\n",
                     r.from_cache, r.boards.size(), o.fleet.cache_dir.c_str());
    if (o.part.empty()) {
        print_fleet(r.boards, o.json, o.plot_dir, o.report_dir);
        return;
    }
    const nlohmann::json campaign = {{"logs", logs}, {"options", fleet::analysis_options(o.fleet)}};
    fleet::write_fleet_part({campaign, build_id(), o.shard.first, o.shard.second, r.items, std::move(r.boards)},
                            o.part);
    std::fprintf(stderr, "fleet: shard %zu/%zu: %zu of %zu boards in %s (driftlab merge PART... summarises them)\n",
                 o.shard.first, o.shard.second, r.items.size(), logs.size(), o.part.c_str());
}

}  // namespace

void register_fleet(CLI::App& app) {
    auto o = std::make_shared<FleetCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "fleet",
        "Characterise a batch of boards from their logs: each board's drift, noise and gap verdict, the "
        "batch's spread, the boards that stand out");
    cmd->add_option("logs", o->inputs, "Canonical logs, or folders of them (their *.csv, by name)")
        ->required()
        ->check(non_empty_path());
    cmd->add_option("--channel", o->fleet.board.channels, "Channels to analyse (default: every channel of each log)")
        ->delimiter(',');
    cmd->add_option("--model", o->fleet.model_path,
                    "Model file of the unit the boards are built to, for the gap diagnosis (default: the paper's)")
        ->check(non_empty_path());
    cmd->add_flag("--no-gap", o->no_gap, "Leave the gap diagnosis out (seconds a board instead of tens)");
    cmd->add_option("--replicates", o->fleet.board.replicates, "The gap diagnosis's replicates (default 40)")
        ->check(whole_number_in(10, 100000));
    cmd->add_option("--seed", o->fleet.board.seed, "The gap diagnosis's seed")->check(seed_number());
    cmd->add_option("--cache", o->cache_dir,
                    "Keep each board's result here and read back those analysed before with the same options (default "
                    "$XDG_CACHE_HOME/driftlab/fleet or ~/.cache/driftlab/fleet)")
        ->check(non_empty_path());
    cmd->add_flag("--no-cache", o->no_cache, "Analyse every log, keep nothing");
    CLI::Option* part = add_shard_options(cmd, o->shard, o->part, "logs");
    cmd->add_flag("--json", o->json, "Print JSON (keys: boards, batch, false_standout, standouts)")->excludes(part);
    cmd->add_option("--plot", o->plot_dir, "Draw per channel every board's robust z-score by parameter in this folder")
        ->check(non_empty_path())
        ->excludes(part);
    cmd->add_option("--report", o->report_dir, "Write fleet.md with its figures into this folder")
        ->check(non_empty_path())
        ->excludes(part);
    cmd->callback([o] { run(*o); });
}

}  // namespace driftlab::host::cli
