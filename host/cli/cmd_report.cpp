// `driftlab report LOG -o report.html`: the drift fit, whiteness and Allan analysis of a log in one
// self-contained HTML file (host/view/html_report; docs/analysis.md §6).
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/fit/file_analysis.hpp"
#include "host/stats/rate_unit.hpp"
#include "host/util/error.hpp"
#include "host/util/input_file.hpp"
#include "host/util/output_file.hpp"
#include "host/util/output_folder.hpp"
#include "host/view/analysis_notes.hpp"
#include "host/view/fit_view.hpp"
#include "host/view/html_report.hpp"
#include "host/view/json_out.hpp"
#include "host/view/nav_section.hpp"

namespace driftlab::host::cli {
namespace {

struct ReportCommandOptions {
    fit::FileAnalysisRequest request;
    std::string output = "report.html";
    bool json = false;
    bool no_plots = false;
    std::vector<std::string> units;  ///< --unit [COLUMN:]UNIT, plain tables
    std::string nav_path;            ///< --nav: what nav --json printed
};

// --nav's JSON, read before the analysis so that a wrong file costs nothing.
std::optional<nlohmann::json> read_nav(const std::string& path) {
    if (path.empty()) return std::nullopt;
    const std::string text = read_small_file(path, kMaxJsonFileBytes);
    nlohmann::json nav;
    try {
        nav = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw DataError(path, 0, "not JSON (byte " + std::to_string(e.byte) + "): give what nav --json prints");
    }
    view::nav_section(nav, path);  // refuses what nav --json does not print
    return nav;
}

/// Gives the plain table's analysed columns the units of --unit, so that the page reads in them (Allan headers,
/// noise terms in navigation units). A column --unit names that is not among them is refused, naming the columns.
void assign_units(const stats::UnitAssignment& units, fit::FileAnalysis& file) {
    std::vector<std::string> columns;
    for (const auto& s : file.series) columns.push_back(s.name);
    stats::refuse_unknown_columns(units, columns, file.path);
    for (auto& s : file.series)
        if (const auto unit = units.for_column(s.name); unit && s.analysis) s.analysis->data.unit = unit->name;
}

void run(const ReportCommandOptions& opts) {
    refuse_writing_over_input(opts.output, "-o", opts.request.path, "log");
    const stats::UnitAssignment units = stats::parse_unit_assignment(opts.units, "--unit");
    if (!opts.units.empty() && fit::is_canonical_log(opts.request.path))
        throw UsageError("--unit: " + opts.request.path +
                         " is a driftlab log: its channels are in counts, whose physical units are known");
    make_folder_of(opts.output, "report");  // before the work, as --plot does
    const std::optional<nlohmann::json> nav = read_nav(opts.nav_path);
    fit::FileAnalysis file = fit::analyse_file(opts.request);
    assign_units(units, file);
    // A page of empty tables had been written where no series could be analysed; one that failed is shown there.
    if (file.failures() == file.series.size()) throw_if_failed(file, false);
    view::ReportOptions ropts;
    ropts.plots = !opts.no_plots;
    if (nav) ropts.nav = &*nav, ropts.nav_path = opts.nav_path;
    const std::string html = view::render_html_report(file, ropts);
    std::ofstream out(opts.output, std::ios::binary);
    out << html;
    out.close();
    if (!out) throw DeviceError(opts.output, "cannot write the report");
    if (opts.json) {
        nlohmann::json j = view::fit_to_json(file);
        j["report"] = opts.output;
        view::write_json(std::cout, j);
    } else {
        std::cout << "wrote " << opts.output << " (" << html.size() / 1024 << " KiB)\n";
    }
    view::print_file_notes(file, opts.json);
    throw_if_failed(file, false);  // the reasons are in the page, not on the terminal
}

}  // namespace

void add_unit_option(CLI::App* cmd, std::vector<std::string>& units, bool takes_phase) {
    cmd->add_option("--unit", units,
                    "Plain tables: [COLUMN:]UNIT, the unit of a column's samples (of every other column without "
                    "COLUMN:), for noise terms in navigation units: " +
                        stats::rate_unit_names(stats::RateQuantity::angular_rate) + ", " +
                        stats::rate_unit_names(stats::RateQuantity::acceleration) +
                        (takes_phase ? "; with --kind phase, the integral's (" + stats::phase_unit_names() + ")" : "") +
                        "; repeat for several columns")
        ->allow_extra_args(false);  // one value an occurrence: `--unit mg LOG` had taken the log for a unit
}

void register_report(CLI::App& app) {
    auto opts = std::make_shared<ReportCommandOptions>();
    CLI::App* cmd =
        app.add_subcommand("report", "Write one self-contained HTML report (fit, whiteness, Allan, figures)");
    add_analysis_input_options(cmd, opts->request);
    cmd->add_option("-o,--output", opts->output, "HTML file to write (default report.html)")->check(non_empty_path());
    cmd->add_flag("--json", opts->json, "Also print the fit results as JSON (same keys as `fit --json`)");
    cmd->add_option("--nav", opts->nav_path, "Add a navigation section: what nav --json printed for a run of this unit")
        ->check(non_empty_path());
    cmd->add_flag("--no-plots", opts->no_plots, "Leave the figures out (no gnuplot needed)");
    add_unit_option(cmd, opts->units);
    cmd->callback([opts] { run(*opts); });
}

}  // namespace driftlab::host::cli
