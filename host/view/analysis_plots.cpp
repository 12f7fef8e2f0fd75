// Paper figures as plots; see analysis_plots.hpp.
#include "host/view/analysis_plots.hpp"

#include <limits>

#include "host/fit/drift_model.hpp"
#include "host/log/log_data.hpp"

namespace driftlab::host::view {
namespace {

PlotSeries thinned(const std::string& title, const std::vector<double>& x, const std::vector<double>& y,
                   SeriesStyle style) {
    PlotSeries s;
    s.title = title;
    s.style = style;
    const std::size_t step = x.size() > kMaxPlotPoints ? (x.size() + kMaxPlotPoints - 1) / kMaxPlotPoints : 1;
    for (std::size_t k = 0; k < x.size(); k += step) {
        s.x.push_back(x[k]);
        s.y.push_back(y[k]);
    }
    return s;
}

std::string value_label(const fit::DriftAnalysis& a) {
    return a.data.name + (a.data.unit.empty() ? "" : " [" + a.data.unit + "]");
}

}  // namespace

std::optional<Plot> raw_vs_smoothed_plot(const fit::DriftAnalysis& a) {
    if (a.data.raw_values.size() != a.data.values.size() || a.data.raw_values.empty()) return std::nullopt;
    Plot p;
    p.title = a.data.name + ": raw codes and on-board least-squares output (paper Fig. 2)";
    p.x_label = "t [s]";
    p.y_label = value_label(a);
    // A lost RAW frame's code (-1) is no reading: a break in the steps, not a drop to -1 that flattens the rest.
    std::vector<double> raw = a.data.raw_values;
    for (double& v : raw)
        if (v == kLostRawCode) v = std::numeric_limits<double>::quiet_NaN();
    p.series.push_back(thinned("raw", a.data.t_s, raw, SeriesStyle::steps));
    p.series.back().color = "#9a9a9a";
    p.series.back().line_width = 1.0;
    p.series.push_back(thinned("least squares", a.data.t_s, a.data.values, SeriesStyle::lines));
    p.series.back().color = "#1f5fbf";
    return p;
}

Plot drift_fit_plot(const fit::DriftAnalysis& a) {
    Plot p;
    p.title = a.data.name + ": data and eq. 1 fit (paper Fig. 3)";
    p.x_label = "t [s]";
    p.y_label = value_label(a);
    p.series.push_back(thinned("data", a.data.t_s, a.data.values, SeriesStyle::points));
    p.series.back().color = "#7f9fcf";
    std::vector<double> model(a.data.t_s.size());
    for (std::size_t k = 0; k < model.size(); ++k) model[k] = fit::drift_model(a.fit.parameters, a.data.t_s[k]);
    p.series.push_back(thinned("C1 (1 - exp(-t/T)) + C2", a.data.t_s, model, SeriesStyle::lines));
    p.series.back().color = "#c0392b";
    p.series.back().line_width = 2.0;
    return p;
}

Plot autocorrelation_plot(const fit::DriftAnalysis& a) {
    const auto& w = a.whiteness;
    Plot p;
    p.title = a.data.name + ": residual autocorrelation, mean of " + std::to_string(w.sequences_used) +
              " sequences (paper Fig. 4)";
    p.x_label = "lag [s]";
    p.y_label = "normalised autocorrelation";
    PlotSeries rho;
    rho.title = "ensemble mean";
    rho.style = SeriesStyle::lines;
    rho.color = "#1f5fbf";
    PlotSeries upper, lower;
    upper.title = "+-2 sigma";
    upper.dashed = lower.dashed = true;
    upper.color = lower.color = "#555555";
    for (std::size_t d = 0; d < w.ensemble_rho.size(); ++d) {
        const double lag_s = static_cast<double>(d) * w.sample_period_s;
        rho.x.push_back(lag_s);
        rho.y.push_back(w.ensemble_rho[d]);
        upper.x.push_back(lag_s);
        upper.y.push_back(w.bound);
        lower.x.push_back(lag_s);
        lower.y.push_back(-w.bound);
    }
    p.series = {rho, upper, lower};
    p.y_range = std::make_pair(-0.3, 1.05);
    return p;
}

}  // namespace driftlab::host::view
