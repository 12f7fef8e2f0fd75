// `driftlab whiteness LOG`: the residual of the eq. 1 fit tested for whiteness per channel, as in the paper's
// Fig. 4 (ensemble autocorrelation, +-2 sigma bounds) plus a Ljung–Box test (docs/analysis.md §3).
#include <cstdio>
#include <iostream>
#include <memory>

#include "host/cli/commands.hpp"
#include "host/fit/file_analysis.hpp"
#include "host/report/analysis_json.hpp"
#include "host/report/analysis_plots.hpp"
#include "host/report/json_out.hpp"

namespace driftlab::host::cli {
namespace {

struct WhitenessCommandOptions {
    fit::FileAnalysisRequest request;
    bool json = false;
    std::string plot_dir;
};

void print_text(const fit::FileAnalysis& file) {
    std::cout << file.path << "\n";
    print_file_notes(file, false);
    std::printf("%-10s %9s %9s %8s %11s %9s %11s  %s\n", "channel", "inside", "bound", "M x L", "LB Q(h)", "LB p",
                "tau [smp]", "verdict");
    for (const auto& s : file.series) {
        if (!s.analysis) {
            std::printf("%-10s error: %s\n", s.name.c_str(), s.error.c_str());
            continue;
        }
        const auto& w = s.analysis->whiteness;
        char mxl[32];
        std::snprintf(mxl, sizeof mxl, "%zux%zu", w.sequences_used, w.sequence_samples);
        char q[32];
        std::snprintf(q, sizeof q, "%.2f(%zu)", w.ljung_box.statistic, w.ljung_box.lags);
        std::printf("%-10s %8.1f%% %9.4f %8s %11s %9.3g %11.2f  %s\n", s.name.c_str(), 100.0 * w.fraction_inside,
                    w.bound, mxl, q, w.ljung_box.p_value, w.autocorrelation_time.tau, w.white ? "white" : "NOT white");
        print_analysis_warnings(*s.analysis);
    }
}

void run(const WhitenessCommandOptions& opts) {
    const fit::FileAnalysis file = fit::analyse_file(opts.request);
    if (opts.json) {
        nlohmann::json out = {{"file", file.path}, {"channels", nlohmann::json::object()}};
        for (const auto& s : file.series)
            out["channels"][s.name] =
                s.analysis ? nlohmann::json{{"whiteness", report::whiteness_json(s.analysis->whiteness, true)},
                                            {"warnings", s.analysis->warnings}}
                           : nlohmann::json{{"error", s.error}};
        report::write_json(std::cout, out);
        print_file_notes(file, true);
    } else {
        print_text(file);
    }
    if (!opts.plot_dir.empty())
        for (const auto& s : file.series)
            if (s.analysis)
                report::render_plot(report::autocorrelation_plot(*s.analysis), opts.plot_dir, "fig4_" + s.name);
    throw_if_failed(file, !opts.json);
}

}  // namespace

void register_whiteness(CLI::App& app) {
    auto opts = std::make_shared<WhitenessCommandOptions>();
    CLI::App* cmd =
        app.add_subcommand("whiteness", "Test the residual of the drift fit for whiteness (paper eqs. 2-4)");
    add_analysis_input_options(cmd, opts->request);
    cmd->add_flag("--json", opts->json,
                  "Print JSON (keys: channels.<name>.whiteness.{fraction_inside,ljung_box_p,white,"
                  "ensemble_autocorrelation,...})");
    cmd->add_option("--plot", opts->plot_dir, "Write Fig. 4 as PNG and SVG into this folder")->check(non_empty_path());
    cmd->callback([opts] { run(*opts); });
}

}  // namespace driftlab::host::cli
