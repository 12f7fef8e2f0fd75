// The text and plots of the drift fit; see fit_view.hpp.
#include <algorithm>
#include <cmath>
#include <iostream>

#include "host/util/format_number.hpp"
#include "host/util/units.hpp"
#include "host/view/analysis_notes.hpp"
#include "host/view/analysis_plots.hpp"
#include "host/view/fit_view.hpp"

namespace driftlab::host::view {
namespace {

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

// Each series' estimates with their 95 % intervals (widened beside them where the residual is not white) and its
// whiteness in one line.
void print_estimates(const fit::FileAnalysis& file) {
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

}  // namespace

void print_fit_table(const fit::FileAnalysis& file) {
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
    print_estimates(file);
}

void write_fit_plots(const fit::FileAnalysis& file, const std::string& dir) {
    for (const auto& s : file.series) {
        if (!s.analysis) continue;
        if (auto fig2 = raw_vs_smoothed_plot(*s.analysis)) render_plot(*fig2, dir, "fig2_" + s.name);
        render_plot(drift_fit_plot(*s.analysis), dir, "fig3_" + s.name);
        render_plot(autocorrelation_plot(*s.analysis), dir, "fig4_" + s.name);
    }
}

}  // namespace driftlab::host::view
