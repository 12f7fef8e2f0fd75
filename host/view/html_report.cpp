// HTML report; see html_report.hpp.
#include "host/view/html_report.hpp"

#include <ctime>

#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/units.hpp"
#include "host/view/allan_section.hpp"
#include "host/view/analysis_plots.hpp"
#include "host/view/gnuplot.hpp"
#include "host/view/html.hpp"
#include "host/view/nav_section.hpp"
#include "host/view/recording_section.hpp"

namespace driftlab::host::view {
namespace {

constexpr const char* kStyle =
    "body{font-family:sans-serif;max-width:1100px;margin:2em auto;color:#222}"
    "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #bbb;padding:3px 8px;text-align:right}"
    "th{background:#eee}td:first-child,.recording td,.recording th{text-align:left}.bad{color:#b00}.good{color:#070}"
    ".warn{background:#fff4e0;border-left:4px solid #e0a000;padding:4px 8px;margin:4px 0}"
    "figure{margin:1em 0}figcaption{font-size:90%;color:#555}svg{max-width:100%;height:auto}";

/// gnuplot's SVG with its XML prolog removed and its element ids made unique within the page.
std::string inline_svg(std::string svg, std::size_t index) {
    const auto start = svg.find("<svg");
    if (start != std::string::npos) svg.erase(0, start);
    const std::string prefix = "f" + std::to_string(index) + "_";
    for (const std::string id : {"gpPt", "gnuplot_canvas", "textbox", "gpBkgnd", "gpDot"}) {
        std::size_t pos = 0;
        while ((pos = svg.find(id, pos)) != std::string::npos) {
            svg.insert(pos, prefix);
            pos += prefix.size() + id.size();
        }
    }
    return svg;
}

struct Figures {
    bool available = true;
    std::string error;
    std::size_t count = 0;
    std::string html;

    void add(const Plot& plot, const std::string& caption) {
        if (!available) return;
        try {
            html += "<figure>" + inline_svg(render_svg(plot), count++) + "<figcaption>" + html_escape(caption) +
                    "</figcaption></figure>\n";
        } catch (const Error& e) {
            available = false;
            error = e.what();
        }
    }
};

// Values carry the digits their standard error justifies (two on the error), not a fixed count: 12.342 +- 0.051,
// not 12.3417 +- 0.0512.
std::string estimate_cell(const fit::Estimate& e) { return value_with_error(e.value, e.stderr_, "&plusmn;"); }

std::string ci_cell(const fit::Estimate& e) {
    return "[" + to_precision_of(e.ci95[0], e.stderr_) + ", " + to_precision_of(e.ci95[1], e.stderr_) + "]";
}

// Table 1: the fitted eq. 1 per channel, in counts and in the physical unit.
std::string drift_table(const fit::FileAnalysis& file) {
    std::string h;
    h += "<h2>Turn-on drift, eq. 1: C1 (1 &minus; exp(&minus;t/T)) + C2</h2>\n";
    h += "<table><tr><th>channel</th><th>C1</th><th>C2</th><th>T [s]</th><th>unit</th><th>status</th><th>n</th>"
         "<th>rms</th></tr>\n";
    std::string undetermined;
    bool accel_shown = false;
    for (const auto& s : file.series) {
        if (!s.analysis) {
            h += "<tr><td>" + html_escape(s.name) + "</td><td colspan=\"7\" class=\"bad\">" + html_escape(s.error) +
                 "</td></tr>\n";
            continue;
        }
        const fit::DriftAnalysis& a = *s.analysis;
        // The fit's values of parameters the data do not determine are arbitrary (C1 = -6.9e11 counts on a warm log).
        const bool c1_t = a.c1_and_t_determined(), c2_known = a.c2_determined();
        const fit::Estimate &c1_e = a.plain.c1, &c2_e = a.plain.c2;
        std::string c1 = c1_t ? to_precision_of(c1_e.value, c1_e.stderr_) : fit::kNotDetermined;
        std::string c2 = c2_known ? to_precision_of(c2_e.value, c2_e.stderr_) : fit::kNotDetermined;
        if (a.data.channel) {
            const Channel c = *a.data.channel;
            const std::string unit = physical_unit(c).name;
            accel_shown |= c != Channel::gyro;
            // A standard error in counts is one in the physical unit too, scaled alike.
            const auto physical = [c](double v, const fit::Estimate& e) {
                return to_precision_of(v, counts_to_physical(c, e.stderr_));
            };
            if (c1_t) c1 += " (" + physical(counts_to_physical(c, c1_e.value), c1_e) + " " + unit + ")";
            if (c2_known)
                c2 += " (" + physical(level_to_physical(c, c2_e.value), c2_e) + " " + unit + " from mid-scale)";
        }
        h += "<tr><td>" + html_escape(s.name) + "</td><td>" + c1 + "</td><td>" + c2 + "</td><td>" +
             (c1_t ? to_precision_of(a.plain.t_s.value, a.plain.t_s.stderr_) : fit::kNotDetermined) + "</td><td>" +
             html_escape(a.data.unit.empty() ? "-" : a.data.unit) + "</td><td>" + fit::fit_status_words(a.fit.status) +
             "</td><td>" + std::to_string(a.fit.n) + "</td><td>" + sig(a.fit.rms, 3) + "</td></tr>\n";
        if (!c1_t)
            undetermined += "<p><b>" + html_escape(s.name) + ":</b> " + fit::kNotDetermined + ": " +
                            html_escape(a.undetermined_reason()) + ".</p>\n";
    }
    h += "</table>\n" + undetermined;
    if (accel_shown) h += "<p>Note: " + html_escape(kAccelScaleNote) + ".</p>\n";

    return h;
}

// Each estimate's standard error with its plain and widened 95 % intervals.
std::string interval_table(const std::vector<const fit::DriftAnalysis*>& ok) {
    std::string h;
    h += "<h3>Standard errors and 95 % intervals</h3>\n<p>Plain intervals assume a white residual; the widened ones "
         "scale the standard errors by the square root of the residual's integrated autocorrelation time.</p>\n";
    h += "<table><tr><th>channel</th><th>parameter</th><th>value &plusmn; se</th><th>95 %</th><th>95 % widened</th>"
         "</tr>\n";
    for (const fit::DriftAnalysis* a : ok) {
        const auto row = [&](const char* p, const fit::Estimate& e, const fit::Estimate& w, bool determined) {
            h += "<tr><td>" + html_escape(a->data.name) + "</td><td>" + p + "</td>" +
                 (determined ? "<td>" + estimate_cell(e) + "</td><td>" + ci_cell(e) + "</td><td>" + ci_cell(w) + "</td>"
                             : "<td colspan=\"3\">" + std::string(fit::kNotDetermined) + "</td>") +
                 "</tr>\n";
        };
        row("C1", a->plain.c1, a->widened.c1, a->c1_and_t_determined());
        row("C2", a->plain.c2, a->widened.c2, a->c2_determined());
        row("T [s]", a->plain.t_s, a->widened.t_s, a->c1_and_t_determined());
        // What a record far shorter than T determines where C1 and T are not.
        if (a->t_beyond_record) row("C1/T [per s]", a->plain.initial_slope, a->widened.initial_slope, true);
    }
    h += "</table>\n";

    return h;
}

std::string whiteness_table(const std::vector<const fit::DriftAnalysis*>& ok) {
    std::string h;
    // 95.5 % had been quoted here: the normal figure, for a constant standard error. The biased estimate (eq. 3)
    // shrinks with the lag, so over lags 1..L-1 white noise lies inside more often (docs/analysis.md §3).
    h += "<h2>Whiteness of the residual (eqs. 2&ndash;4)</h2>\n<p>Ensemble of M sequences of L seconds. For a white "
         "residual about 98.9 % of the lags 1 to L&minus;1 lie inside &plusmn;2&sigma;: the biased estimate (eq. 3) "
         "shrinks at large lags, so more than the 95.4 % of a normal variable (docs/analysis.md &sect;3; the paper's "
         "98 % agrees). The verdict is the Ljung&ndash;Box test at 5 %.</p>\n";
    h += "<table><tr><th>channel</th><th>M &times; L</th><th>inside &plusmn;2&sigma;</th><th>Ljung&ndash;Box Q (h)</th>"
         "<th>p</th><th>autocorrelation time [samples]</th><th>interval widening</th><th>verdict</th></tr>\n";
    for (const fit::DriftAnalysis* a : ok) {
        const auto& w = a->whiteness;
        h += "<tr><td>" + html_escape(a->data.name) + "</td><td>" + std::to_string(w.sequences_used) + " &times; " +
             sig(w.sequence_length_s, 4) + " s</td><td>" + fixed(100.0 * w.fraction_inside, 1) + " %</td><td>" +
             fixed(w.ljung_box.statistic, 2) + " (" + std::to_string(w.ljung_box.lags) + ")</td><td>" +
             sig(w.ljung_box.p_value, 3) + "</td><td>" + fixed(w.autocorrelation_time.tau, 2) + "</td><td>&times;" +
             fixed(a->widened.inflation, 2) + "</td><td class=\"" + (w.white ? "good\">white" : "bad\">not white") +
             "</td></tr>\n";
    }
    h += "</table>\n";
    for (const fit::DriftAnalysis* a : ok)
        for (const auto& warning : a->warnings)
            h += "<div class=\"warn\"><b>" + html_escape(a->data.name) + ":</b> " + html_escape(warning) + "</div>\n";

    return h;
}

// The paper's Fig. 2-4 per channel and the Allan deviations, as images in the page.
std::string figures(const std::vector<const fit::DriftAnalysis*>& ok, const AllanSection& allan,
                    const ReportOptions& options) {
    std::string h;
    h += "<h2>Figures</h2>\n";
    if (!options.plots) {
        h += "<p>Figures not requested.</p>\n";
    } else {
        Figures figs;
        for (const fit::DriftAnalysis* a : ok) {
            if (auto fig2 = raw_vs_smoothed_plot(*a)) figs.add(*fig2, a->data.name + ": raw vs smoothed (Fig. 2)");
            figs.add(drift_fit_plot(*a), a->data.name + ": data and fitted eq. 1 (Fig. 3)");
            figs.add(autocorrelation_plot(*a), a->data.name + ": residual autocorrelation with bounds (Fig. 4)");
        }
        for (std::size_t i = 0; i < allan.plots.size(); ++i)
            figs.add(allan.plots[i], allan.plot_names[i] + ": overlapping Allan deviation with 68 % intervals");
        h += figs.available ? figs.html : "<p class=\"bad\">Figures unavailable: " + html_escape(figs.error) + "</p>\n";
    }
    return h;
}

// `report --nav`: the run's table and its figures.
std::string navigation(const ReportOptions& options) {
    const NavSection nav = nav_section(*options.nav, options.nav_path);
    std::string h = nav.html;
    if (!options.plots) return h + "<p>Figures not requested.</p>\n";
    Figures figs;
    for (const NamedPlot& p : nav.plots) figs.add(p.plot, p.plot.title);
    return h +
           (figs.available ? figs.html : "<p class=\"bad\">Figures unavailable: " + html_escape(figs.error) + "</p>\n");
}

}  // namespace

std::string render_html_report(const fit::FileAnalysis& file, const ReportOptions& options) {
    std::vector<const fit::DriftAnalysis*> ok;
    for (const auto& s : file.series)
        if (s.analysis) ok.push_back(&*s.analysis);

    std::string h;
    h += "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>driftlab report: " +
         html_escape(file.path) + "</title><style>" + kStyle + "</style></head><body>\n";
    const std::time_t now = std::time(nullptr);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    h += "<h1>Drift analysis</h1>\n<p>File <code>" + html_escape(file.path) + "</code> (" +
         (file.canonical_log ? "driftlab log" : "plain table") + "), generated " + stamp + " by driftlab.</p>\n";
    for (const auto& note : file.notes) h += "<p>Note: " + html_escape(note) + "</p>\n";
    if (file.log) h += recording_section(*file.log);

    h += drift_table(file);
    h += interval_table(ok);
    h += whiteness_table(ok);
    // Allan analysis.
    h += "<h2>Allan analysis</h2>\n";
    AllanSection allan;
    try {
        allan = allan_section(ok);
        h += allan.html;
    } catch (const std::exception& e) {
        h += "<p class=\"bad\">Allan analysis failed: " + html_escape(e.what()) + "</p>\n";
    }

    h += figures(ok, allan, options);
    if (options.nav) h += navigation(options);
    h += "</body></html>\n";
    return h;
}

}  // namespace driftlab::host::view
