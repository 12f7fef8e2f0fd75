// `driftlab merge`: a sharded campaign's parts (gap-eval: host/gap_eval/eval_parts; nav-eval: host/nav/nav_parts;
// fleet: host/fleet/fleet_parts) scored as the one-process run scores them (docs/cluster.md).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/cli/fleet_output.hpp"
#include "host/cli/gap_eval_output.hpp"
#include "host/cli/nav_eval_output.hpp"
#include "host/fleet/fleet_parts.hpp"
#include "host/gap_eval/eval_parts.hpp"
#include "host/nav/nav_parts.hpp"
#include "host/util/error.hpp"
#include "host/util/output_folder.hpp"
#include "host/util/part_file.hpp"

namespace driftlab::host::cli {
namespace {

struct MergeOptions {
    std::vector<std::string> parts;
    bool json = false;
    std::string plot_dir;
    std::string report_dir;
    std::string output;  ///< -o: where a sizes stage's merge goes
};

void run(const MergeOptions& o) {
    if (!o.plot_dir.empty()) make_output_folder(o.plot_dir, "plot");
    if (!o.report_dir.empty()) make_output_folder(o.report_dir, "report");
    // The first part says which campaign it is; the merge of that kind checks every other.
    const std::string kind = part_kind(o.parts.front());
    if (kind == nav::kNavPartKind) {
        const nav::NavPart whole = nav::merge_nav_parts(o.parts);
        print_nav_eval(whole.campaign, whole.runs, o.json, o.plot_dir);
        return;
    }
    if (kind == gap::kSizesPartKind) {
        if (o.output.empty())
            throw UsageError("merge: " + o.parts.front() +
                             " is a gap-eval sizes part: -o SIZES names the file its merge is written to");
        const gap::SizesPart whole = gap::merge_sizes_parts(o.parts);
        gap::write_sizes_part(whole, o.output);
        std::fprintf(stderr, "merge: a_50 of %zu generators in %s (gap-eval --sizes %s runs the cases)\n",
                     whole.sizes.size(), o.output.c_str(), o.output.c_str());
        return;
    }
    if (!o.output.empty()) throw UsageError("merge -o: only a gap-eval sizes stage's merge is written to a file");
    if (kind == fleet::kFleetPartKind) {
        print_fleet(fleet::merge_fleet_parts(o.parts).boards, o.json, o.plot_dir, o.report_dir);
        return;
    }
    const gap::EvalPart whole = gap::merge_parts(o.parts);
    print_gap_eval(whole.options, whole.sizes, whole.cases, whole.pairs, o.json, o.plot_dir);
}

}  // namespace

void register_merge(CLI::App& app) {
    auto o = std::make_shared<MergeOptions>();
    CLI::App* cmd = app.add_subcommand("merge",
                                       "Score a sharded gap-eval, nav-eval or fleet campaign from its parts, exactly "
                                       "as the one-process run prints it");
    cmd->add_option("parts", o->parts,
                    "Every part of the campaign (gap-eval, nav-eval or fleet --shard K/N -o PART), in any order")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_flag("--json", o->json, "Print JSON, as the campaign's command does with --json");
    cmd->add_option("--plot", o->plot_dir,
                    "Also draw the campaign's plots in this folder, as its command's --plot does")
        ->check(non_empty_path());
    cmd->add_option("--report", o->report_dir, "A fleet: also write fleet.md with its figures in this folder")
        ->check(non_empty_path());
    cmd->add_option("-o,--output", o->output,
                    "A gap-eval sizes stage (--measure-sizes): the file its merge is written to, for gap-eval --sizes")
        ->check(non_empty_path());
    cmd->callback([o] { run(*o); });
}

}  // namespace driftlab::host::cli
