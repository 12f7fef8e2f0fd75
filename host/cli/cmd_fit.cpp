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
#include "host/report/analysis_json.hpp"
#include "host/report/analysis_plots.hpp"
#include "host/report/json_out.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/units.hpp"

namespace driftlab::host::cli {
namespace {

struct FitCommandOptions {
    fit::FileAnalysisRequest request;
    bool json = false;
    std::string plot_dir;
};

/// An estimate and its interval written to the precision of its standard error: a table in g or rad/s shows its
/// digits (C1 = -0.000213), where fixed decimals had printed -0.000.
std::string at_precision(const fit::Estimate& e, double v) { return to_precision_of(v, e.stderr_); }

std::string interval(const fit::Estimate& e, const std::array<double, 2>& ci) {
    return "[" + at_precision(e, ci[0]) + ", " + at_precision(e, ci[1]) + "]";
}

/// Rows of cells in columns as wide as their widest cell: a value such as -6.92737e+11 or the status
/// "not converged (iteration limit)" had pushed the rest of its row out of line under fixed widths. A row of two cells
/// (a series that failed) keeps its second cell whole, beside the first column.
void print_columns(const std::vector<std::vector<std::string>>& rows) {
    std::vector<std::size_t> width(rows.front().size(), 0);
    for (const auto& row : rows)
        if (row.size() == width.size())
            for (std::size_t i = 0; i < row.size(); ++i) width[i] = std::max(width[i], row[i].size());
    for (const auto& row : rows) {
        std::string line;
        for (std::size_t i = 0; i < row.size(); ++i) {
            line += row[i];
            if (i + 1 < row.size()) line.append(width[i] - std::min(width[i], row[i].size()) + 2, ' ');
        }
        std::cout << line << "\n";
    }
}

void print_table(const fit::FileAnalysis& file) {
    std::cout << file.path << "\n";
    print_file_notes(file, false);
    // A log's values are A/D counts with the physical value beside them, a plain table's are in its own unit; the
    // file says which, also when no series of it could be analysed.
    const std::string unit = file.canonical_log ? "[counts]" : "[table unit]";
    std::vector<std::vector<std::string>> rows = {
        {"channel", "C1 " + unit + (file.canonical_log ? " (physical)" : ""),
         "C2 " + unit + (file.canonical_log ? " (physical from mid-scale)" : ""), "T [s]", "status", "rms " + unit,
         "residual"}};
    std::vector<std::string> undetermined;
    bool accel_shown = false;
    for (const auto& s : file.series) {
        if (!s.analysis) {
            rows.push_back({s.name, "error: " + s.error});
            continue;
        }
        const fit::DriftAnalysis& a = *s.analysis;
        const bool c1_t = a.c1_and_t_determined(), c2_known = a.c2_determined();
        std::string c1 = c1_t ? at_precision(a.plain.c1, a.plain.c1.value) : fit::kNotDetermined;
        std::string c2 = c2_known ? at_precision(a.plain.c2, a.plain.c2.value) : fit::kNotDetermined;
        if (a.data.channel) {
            const Channel c = *a.data.channel;
            const std::string name = physical_unit(c).name;
            accel_shown |= c != Channel::gyro;
            const auto physical = [c](const fit::Estimate& e, double v) {
                return to_precision_of(v, std::fabs(counts_to_physical(c, e.stderr_)));
            };
            if (c1_t) c1 += " (" + physical(a.plain.c1, counts_to_physical(c, a.plain.c1.value)) + " " + name + ")";
            if (c2_known) c2 += " (" + physical(a.plain.c2, level_to_physical(c, a.plain.c2.value)) + " " + name + ")";
        }
        rows.push_back({s.name, c1, c2, c1_t ? at_precision(a.plain.t_s, a.plain.t_s.value) : fit::kNotDetermined,
                        fit::fit_status_words(a.fit.status), significant(a.fit.rms, 4),
                        a.whiteness.white ? "white" : "NOT white"});
        if (!c1_t) undetermined.push_back(s.name + ": " + fit::kNotDetermined + ": " + a.undetermined_reason());
    }
    print_columns(rows);
    for (const auto& line : undetermined) std::cout << line << "\n";
    if (accel_shown) std::cout << "note: " << kAccelScaleNote << "\n";
    for (const auto& s : file.series) {
        if (!s.analysis) continue;
        const fit::DriftAnalysis& a = *s.analysis;
        std::cout << "\n"
                  << s.name << ": n = " << a.fit.n << ", t = " << fixed_point(a.data.t_s.front(), 3) << " .. "
                  << fixed_point(a.data.t_s.back(), 3) << " s, " << a.fit.iterations << " LM iterations ("
                  << a.fit.solver_stop << ")\n";
        // `per` follows the value (its unit), `note` the intervals.
        const auto row = [&](const char* name, const fit::Estimate& p, const fit::Estimate& w, bool determined,
                             const char* per = "", const char* note = "") {
            std::cout << "  " << name << " = ";
            if (!determined) {
                std::cout << fit::kNotDetermined << " (the fit's value is in --json)\n";
                return;
            }
            std::cout << fit::with_error(p) << per;
            if (std::isfinite(p.stderr_)) {
                std::cout << "  95 % " << interval(p, p.ci95);
                if (!a.whiteness.white) std::cout << "  widened " << interval(p, w.ci95);
            }
            std::cout << note << "\n";
        };
        row("C1", a.plain.c1, a.widened.c1, a.c1_and_t_determined());
        row("C2", a.plain.c2, a.widened.c2, a.c2_determined());
        row("T ", a.plain.t_s, a.widened.t_s, a.c1_and_t_determined());
        // What a record far shorter than T does determine (JSON initial_slope), where C1 and T are not.
        if (a.t_beyond_record)
            row("C1/T", a.plain.initial_slope, a.widened.initial_slope, true, " per s",
                "  (initial slope, the drift rate at power-on)");
        const auto& w = a.whiteness;
        std::cout << "  whiteness: " << fixed_point(100.0 * w.fraction_inside, 1) << " % of lags inside +-2 sigma ("
                  << w.sequences_used << " sequences of " << fixed_point(w.sequence_length_s, 1) << " s), Ljung-Box Q("
                  << w.ljung_box.lags << ") = " << fixed_point(w.ljung_box.statistic, 2)
                  << ", p = " << significant(w.ljung_box.p_value, 3) << " -> " << (w.white ? "white" : "not white")
                  << "\n";
        print_analysis_warnings(a);
    }
}

void write_plots(const fit::FileAnalysis& file, const std::string& dir) {
    for (const auto& s : file.series) {
        if (!s.analysis) continue;
        if (auto fig2 = report::raw_vs_smoothed_plot(*s.analysis)) report::render_plot(*fig2, dir, "fig2_" + s.name);
        report::render_plot(report::drift_fit_plot(*s.analysis), dir, "fig3_" + s.name);
        report::render_plot(report::autocorrelation_plot(*s.analysis), dir, "fig4_" + s.name);
    }
}

void run(const FitCommandOptions& opts) {
    const fit::FileAnalysis file = fit::analyse_file(opts.request);
    if (opts.json) {
        nlohmann::json out = {{"file", file.path}, {"channels", nlohmann::json::object()}};
        for (const auto& s : file.series)
            out["channels"][s.name] = s.analysis ? report::fit_json(*s.analysis) : nlohmann::json{{"error", s.error}};
        report::write_json(std::cout, out);
        print_file_notes(file, true);
    } else {
        print_table(file);
    }
    if (!opts.plot_dir.empty()) write_plots(file, opts.plot_dir);
    throw_if_failed(file, !opts.json);
}

}  // namespace

void print_analysis_warnings(const fit::DriftAnalysis& analysis) {
    for (const auto& warning : analysis.warnings) std::cout << "  warning: " << warning << "\n";
}

void print_note(const std::string& note, bool json) {
    // Beside JSON it goes to the error output, which keeps the standard output one document.
    if (!note.empty()) (json ? std::cerr : std::cout) << "note: " << note << "\n";
}

void print_file_notes(const fit::FileAnalysis& file, bool json) {
    for (const auto& note : file.notes) print_note(note, json);
}

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
