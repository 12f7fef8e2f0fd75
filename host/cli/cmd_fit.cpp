// `driftlab fit LOG`: eq. 1 per channel by Levenberg–Marquardt, Table 1 layout, whiteness of the residual
// (host/fit, host/stats; docs/analysis.md §2–3).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/fit/file_analysis.hpp"
#include "host/util/error.hpp"
#include "host/view/analysis_notes.hpp"
#include "host/view/fit_view.hpp"
#include "host/view/json_out.hpp"

namespace driftlab::host::cli {
namespace {

struct FitCommandOptions {
    fit::FileAnalysisRequest request;
    bool json = false;
    std::string plot_dir;
};

void run(const FitCommandOptions& opts) {
    const fit::FileAnalysis file = fit::analyse_file(opts.request);
    if (opts.json) {
        view::write_json(std::cout, view::fit_to_json(file));
        view::print_file_notes(file, true);
    } else {
        view::print_fit_table(file);
    }
    if (!opts.plot_dir.empty()) view::write_fit_plots(file, opts.plot_dir);
    throw_if_failed(file, !opts.json);
}

}  // namespace

void throw_if_failed(const fit::FileAnalysis& file, bool reasons_printed) {
    if (file.failures() == 0) return;
    if (!reasons_printed) throw DataError(file.path, 0, file.failure_summary());
    // The table's rows give each reason: repeating them all in one line had printed every error twice.
    std::string names;
    for (const auto& s : file.series)
        if (!s.analysis) names += (names.empty() ? "" : ", ") + s.name;
    throw DataError(file.path, 0, "not analysed: " + names + " (the reasons are above)");
}

void add_drop_cut_line_flag(CLI::App* cmd, bool& drop) {
    cmd->add_flag("--drop-cut-line", drop,
                  "Driftlab logs: leave out a last line cut without a newline (a killed writer) and say so, rather "
                  "than refuse the log");
}

void add_analysis_input_options(CLI::App* cmd, fit::FileAnalysisRequest& r) {
    cmd->add_option("log", r.path, "Canonical log (docs/log-format.md) or plain numeric table")
        ->required()
        ->check(non_empty_path());
    cmd->add_option("--channel", r.names, "Channels (or table columns) to analyse; default all")->delimiter(',');
    add_time_range_options(cmd, r.options.t_min_s, r.options.t_max_s);
    add_exclude_option(cmd, r.options.excluded,
                       "a corrupt row or a disturbance; the fit keeps the true times, the whiteness lags join the rows "
                       "either side");
    cmd->add_option(
           "--time-column", r.time_column,
           "Plain tables: the time column [s; ms, us or ns when its name ends _ms, _us or _ns] (default t_s, t, "
           "time, time_s, timestamp...)")
        ->check(non_empty("a column name"));
    // --tau0 as allan and gap spell the period.
    cmd->add_option("--sample-period,--tau0", r.sample_period_s,
                    "Plain tables without a time column: sample period [s] (default 1 s per row)")
        ->check(positive_number());
    add_drop_cut_line_flag(cmd, r.drop_cut_line);
    // More than the residual holds are cut to what it holds, with a warning: the bound only keeps the count a number.
    cmd->add_option("--sequences", r.options.whiteness.sequences, "Whiteness: number M of sequences (paper: 10)")
        ->check(whole_number_in(1, 1000000));
    cmd->add_option("--sequence-length", r.options.whiteness.sequence_length_s,
                    "Whiteness: length L of each sequence [s] (paper: 50)")
        ->check(positive_number());
}

void register_fit(CLI::App& app) {
    auto opts = std::make_shared<FitCommandOptions>();
    CLI::App* cmd = app.add_subcommand("fit", "Fit the turn-on drift C1(1-exp(-t/T))+C2 per channel (paper eq. 1)");
    add_analysis_input_options(cmd, opts->request);
    cmd->add_flag("--json", opts->json, "Print JSON (keys: channels.<name>.{C1,C2,T,status,n,rms,whiteness,...})");
    cmd->add_option("--plot", opts->plot_dir, "Write Fig. 2-4 as PNG and SVG into this folder")
        ->check(non_empty_path());
    cmd->callback([opts] { run(*opts); });
}

}  // namespace driftlab::host::cli
