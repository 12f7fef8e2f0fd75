// `driftlab whiteness LOG`: the residual of the eq. 1 fit tested for whiteness per channel, as in the paper's
// Fig. 4 (ensemble autocorrelation, +-2 sigma bounds) plus a Ljung–Box test (docs/analysis.md §3).
#include <iostream>
#include <memory>

#include "host/cli/commands.hpp"
#include "host/fit/file_analysis.hpp"
#include "host/view/analysis_notes.hpp"
#include "host/view/json_out.hpp"
#include "host/view/whiteness_view.hpp"

namespace driftlab::host::cli {
namespace {

struct WhitenessCommandOptions {
    fit::FileAnalysisRequest request;
    bool json = false;
    std::string plot_dir;
};

void run(const WhitenessCommandOptions& opts) {
    const fit::FileAnalysis file = fit::analyse_file(opts.request);
    if (opts.json) {
        view::write_json(std::cout, view::whiteness_to_json(file));
        view::print_file_notes(file, true);
    } else {
        view::print_whiteness_table(file);
    }
    if (!opts.plot_dir.empty()) view::write_whiteness_plots(file, opts.plot_dir);
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
