// Allan section of the report; see allan_section.hpp.
#include "host/view/allan_section.hpp"

#include <array>

#include "host/fit/allan_pipeline.hpp"
#include "host/stats/allan_analysis.hpp"
#include "host/stats/noise_terms.hpp"
#include "host/stats/rate_unit.hpp"
#include "host/stats/uniform_grid.hpp"
#include "host/view/html.hpp"

namespace driftlab::host::view {
namespace {

/// Fewest samples for an Allan curve with at least a few octaves.
constexpr std::size_t kMinAllanSamples = 32;

/// Gap slots beyond this share of the grid are worth a warning: the terms skip them, and long taus lose most.
constexpr double kNotableGapShare = 0.2;

// OADEV through the Allan pipeline, so late or missing samples become gaps on the tau0 grid instead of being
// spliced together. The drift is the report's own eq. 1 fit, removed by the caller.
fit::AllanResult oadev(const std::vector<double>& t_s, const std::vector<double>& rate, double tau0_s) {
    fit::AllanRequest request;
    request.remove_drift = false;
    return fit::analyse_allan(t_s, rate, tau0_s, request);
}

PlotSeries curve_series(const stats::AnalysedCurve& c, const std::string& title, const std::string& color) {
    PlotSeries s;
    s.title = title;
    s.style = SeriesStyle::error_bars;
    s.color = color;
    s.x = c.curve.tau_s;
    s.y = c.curve.dev;
    s.y_low = c.ci_low;
    s.y_high = c.ci_high;
    return s;
}

// A term the fit pinned at 0 is not a measured zero: its bound instead (docs/allan.md §6).
std::string term_cell(const stats::NoiseTermFit& terms, std::size_t t) {
    if (!terms.ok) return "-";
    return terms.at_bound[t] ? "not resolved (&le; " + sig(terms.upper_bound[t], 3) + ")" : sig(terms.value[t], 3);
}

std::string named_cell(const std::vector<stats::NamedValue>& values, const std::string& key) {
    for (const stats::NamedValue& nv : values)
        if (nv.key == key) return nv.resolved ? sig(nv.value, 3) : "not resolved (&le; " + sig(nv.upper_bound, 3) + ")";
    return "-";
}

/// The samples' unit: a log channel's counts, or the unit a plain table's column was given (report --unit).
stats::SampleUnit unit_of(const fit::DriftAnalysis& a) {
    return a.data.channel ? stats::unit_of_channel(*a.data.channel) : stats::unit_of_name(a.data.unit);
}

/// The unit's name for a header; a plain column given none is in its data unit.
std::string unit_label(const stats::SampleUnit& u) { return u.name.empty() ? "data unit" : u.name; }

/// The navigation-unit tables: per quantity, its heading, columns (header with unit, physical_terms key).
struct NavigationTable {
    stats::RateQuantity quantity;
    const char* heading;
    std::vector<std::pair<const char*, const char*>> columns;
};

const std::vector<NavigationTable>& navigation_tables() {
    static const std::vector<NavigationTable> tables = {
        {stats::RateQuantity::angular_rate,
         "Rate gyros",
         {{"angle random walk N [&deg;/&radic;h]", "N_deg_per_sqrt_h"},
          {"bias instability B [&deg;/h]", "B_deg_per_h"},
          {"rate random walk K [&deg;/h/&radic;h]", "K_deg_per_h_per_sqrt_h"}}},
        {stats::RateQuantity::acceleration,
         "Accelerometers",
         {{"velocity random walk N [m/s/&radic;h]", "N_m_per_s_per_sqrt_h"},
          {"bias instability B [mg]", "B_mg"},
          {"acceleration random walk K [m/s&sup2;/&radic;s]", "K_m_per_s2_per_sqrt_s"}}},
    };
    return tables;
}

// The table's header: each term in `u` times the power of tau that makes its share of the ADEV a rate
// (noise_terms.hpp); a column U where the channels' units differ (`one_unit` false).
std::string header_row(const std::string& u, bool one_unit) {
    std::string h;
    const std::string unit_column = one_unit ? "" : "<th>U</th>";
    h += "<table><tr><th>channel</th>" + unit_column + "<th>&tau;0 [s]</th><th>OADEV &sigma;(&tau;0) raw [" + u +
         "]</th><th>min OADEV &sigma; residual [" + u + "]</th><th>at &tau; [s]</th>";
    // Each term in U times the power of tau that makes its share of the ADEV a rate (noise_terms.hpp).
    constexpr std::array<const char*, stats::kNoiseTermCount> kTermUnits = {"&middot;s", "/&radic;Hz", "", "/&radic;s",
                                                                            "/s"};
    for (std::size_t t = 0; t < stats::kNoiseTermCount; ++t)
        h += "<th>" + std::string(stats::kNoiseTermSymbols[t]) + " [" + u + kTermUnits[t] + "]</th>";
    h += "</tr>\n";
    return h;
}

// A channel's OADEV as recorded and drift-removed, with the IEEE 952 fit where there is one.
Plot curves_plot(const std::string& name, const std::string& unit, const stats::AnalysedCurve& raw,
                 const stats::AnalysedCurve& residual, const stats::NoiseTermFit& terms) {
    Plot p;
    p.title = name + ": overlapping Allan deviation";
    p.x_label = "tau [s]";
    p.y_label = "OADEV [" + unit + "]";
    p.log_x = p.log_y = true;
    p.series.push_back(curve_series(raw, "as recorded", "#9a9a9a"));
    p.series.push_back(curve_series(residual, "drift removed", "#1f5fbf"));
    if (terms.ok) {
        PlotSeries model;
        model.title = "IEEE 952 fit";
        model.x = residual.curve.tau_s;
        model.y = terms.model_adev;
        model.color = "#c0392b";
        p.series.push_back(model);
    }
    return p;
}

// A channel's row in each table of noise terms in navigation units that its quantity has.
void add_navigation_rows(std::vector<std::string>& rows, const std::string& name, stats::RateQuantity quantity,
                         const std::vector<stats::NamedValue>& physical) {
    for (std::size_t t = 0; t < navigation_tables().size(); ++t) {
        if (navigation_tables()[t].quantity != quantity || physical.empty()) continue;
        rows[t] += "<tr><td>" + name + "</td>";
        for (const auto& column : navigation_tables()[t].columns)
            rows[t] += "<td>" + named_cell(physical, column.second) + "</td>";
        rows[t] += "</tr>\n";
    }
}

}  // namespace

AllanSection allan_section(const std::vector<const fit::DriftAnalysis*>& channels) {
    AllanSection out;
    std::string& h = out.html;
    h += "<p>Overlapping Allan deviation (OADEV, octave tau grid, 68 % intervals from Greenhall EDF with lag-1 "
         "noise identification) of each channel as recorded and after subtracting the fitted eq. 1 drift, on a grid of "
         "tau0 = the rows' median spacing, or their mean where they come in bursts (a grid at the median would be "
         "more than half gaps). "
         "Noise terms: IEEE 952 fit (Q quantisation, N white-noise random walk, B bias instability, K rate random "
         "walk, R ramp) to the drift-free curve, in the samples' unit (counts for a log's channels, a column's "
         "--unit for a plain table) per the tau power; a term the fit pins at 0 is not resolved, and its bound is the "
         "largest value the curve allows (B: the curve's minimum / 0.664). Where a channel is a rate gyro or an "
         "accelerometer, the tables after this one give its terms in the units datasheets quote.</p>\n";
    // Units in the headers: the channels' one unit, or U with a column saying each row's where they differ.
    std::vector<stats::SampleUnit> units;
    for (const fit::DriftAnalysis* a : channels) units.push_back(unit_of(*a));
    bool one_unit = true;
    for (const stats::SampleUnit& u : units) one_unit &= u.name == units.front().name;
    h += header_row(one_unit && !units.empty() ? html_escape(unit_label(units.front())) : "U", one_unit);
    std::string warnings;
    std::vector<std::string> navigation_rows(navigation_tables().size());
    for (std::size_t i = 0; i < channels.size(); ++i) {
        const fit::DriftAnalysis* a = channels[i];
        const std::string name = html_escape(a->data.name);
        const std::string unit_cell = one_unit ? "" : "<td>" + html_escape(unit_label(units[i])) + "</td>";
        if (a->data.values.size() < kMinAllanSamples) {
            h += "<tr><td>" + name + "</td>" + unit_cell +
                 "<td colspan=\"9\">too few samples for an Allan curve</td></tr>\n";
            continue;
        }
        // Not the fit's median spacing: rows in bursts would leave most of a grid at the median empty.
        const double tau0_s = stats::grid_period_s(a->data.t_s);
        const fit::AllanResult raw_result = oadev(a->data.t_s, a->data.values, tau0_s);
        const fit::AllanCurves& raw_curves = raw_result.raw;
        const fit::AllanResult residual_result = oadev(a->data.t_s, a->fit.residual, tau0_s);
        const fit::AllanCurves& residual_curves = residual_result.raw;
        const double gap_share = static_cast<double>(raw_result.gap_samples) / static_cast<double>(raw_result.samples);
        if (gap_share > kNotableGapShare) {
            warnings += "<div class=\"warn\"><b>" + name + ":</b> " + fixed(100.0 * gap_share, 0) + " % of the " +
                        std::to_string(raw_result.samples) + " grid slots at tau0 = " + sig(tau0_s) +
                        " s are gaps (rows " + html_escape(stats::spacing_text(a->data.t_s)) +
                        "); the Allan terms skip them, and no tau exceeds half the longest gap-free stretch, " +
                        sig(raw_result.longest_gap_free_s) + " s.</div>\n";
        }
        const stats::AnalysedCurve& raw = *raw_curves.find(stats::Deviation::oadev);
        const stats::AnalysedCurve& residual = *residual_curves.find(stats::Deviation::oadev);
        if (const auto packing = fit::packing_caveat(residual_result, residual))
            warnings += "<div class=\"warn\"><b>" + name + ":</b> " + html_escape(*packing) + ".</div>\n";
        if (residual.curve.dev.empty()) continue;
        std::size_t best = 0;
        for (std::size_t k = 1; k < residual.curve.dev.size(); ++k)
            if (residual.curve.dev[k] < residual.curve.dev[best]) best = k;
        const stats::NoiseTermFit& terms = residual_curves.terms;
        h += "<tr><td>" + name + "</td>" + unit_cell + "<td>" + sig(tau0_s) + "</td><td>" +
             (raw.curve.dev.empty() ? "-" : sig(raw.curve.dev.front())) + "</td><td>" + sig(residual.curve.dev[best]) +
             "</td><td>" + sig(residual.curve.tau_s[best]) + "</td>";
        for (std::size_t t = 0; t < stats::kNoiseTermCount; ++t) h += "<td>" + term_cell(terms, t) + "</td>";
        h += "</tr>\n";
        const std::vector<stats::NamedValue> physical =
            stats::physical_terms(terms, units[i].quantity, units[i].si_per_unit);
        add_navigation_rows(navigation_rows, name, units[i].quantity, physical);

        out.plots.push_back(curves_plot(a->data.name, unit_label(units[i]), raw, residual, terms));
        out.plot_names.push_back(a->data.name);
    }
    h += "</table>\n";
    // The same terms in the units datasheets quote, where the channel's physical quantity is known.
    for (std::size_t t = 0; t < navigation_tables().size(); ++t) {
        if (navigation_rows[t].empty()) continue;
        h += "<h3>" + std::string(navigation_tables()[t].heading) +
             ": noise terms in navigation units</h3>\n"
             "<table><tr><th>channel</th>";
        for (const auto& column : navigation_tables()[t].columns) h += "<th>" + std::string(column.first) + "</th>";
        h += "</tr>\n" + navigation_rows[t] + "</table>\n";
    }
    h += warnings;
    return out;
}

}  // namespace driftlab::host::view
