// The plots of a gap-eval run; see gap_eval_view.hpp.
#include "host/view/gap_eval_view.hpp"

#include <algorithm>
#include <cmath>

#include "host/stats/binomial_interval.hpp"
#include "host/util/error.hpp"
#include "host/view/gnuplot.hpp"

namespace driftlab::host::view {

using gap::EvalScores;
using gap::SizeScore;

namespace {

// One rate per generator and size with its Clopper-Pearson interval. The generators are set slightly apart in x
// (a few per cent, on the log axis) so that their bars at the same size do not hide each other.
Plot rate_plot(const EvalScores& s, const std::string& title, const std::string& y_label, int SizeScore::*count,
               double target) {
    std::vector<std::string> generators;
    std::vector<double> levels;
    for (const auto& z : s.by_size) {
        if (z.generator == "none") continue;
        if (std::find(generators.begin(), generators.end(), z.generator) == generators.end())
            generators.push_back(z.generator);
        if (std::find(levels.begin(), levels.end(), z.level) == levels.end()) levels.push_back(z.level);
    }
    if (generators.empty()) throw UsageError("gap-eval --plot: the run planted no effect, so there is no size to plot");
    Plot p;
    p.title = title;
    p.x_label = "effect size [multiples of its detection threshold a_50]";
    p.y_label = y_label;
    p.log_x = true;
    const auto [lo, hi] = std::minmax_element(levels.begin(), levels.end());
    p.x_range = std::make_pair(*lo / 1.5, *hi * 1.5);
    p.y_range = std::make_pair(-0.02, 1.02);
    p.x_tics = levels;
    p.key = "outside right top";  // seven generators' bars fill the plot's corners
    p.width_px = 1000;
    for (std::size_t g = 0; g < generators.size(); ++g) {
        PlotSeries series;
        series.title = generators[g];
        series.style = SeriesStyle::error_bars;
        const double offset = std::pow(1.04, static_cast<double>(g) - 0.5 * static_cast<double>(generators.size() - 1));
        for (const auto& z : s.by_size) {
            if (z.generator != generators[g] || z.logs == 0) continue;
            const auto ci =
                stats::clopper_pearson(static_cast<std::size_t>(z.*count), static_cast<std::size_t>(z.logs));
            series.x.push_back(z.level * offset);
            series.y.push_back(static_cast<double>(z.*count) / z.logs);
            series.y_low.push_back(ci.lower);
            series.y_high.push_back(ci.upper);
        }
        p.series.push_back(series);
    }
    PlotSeries line;
    line.title = "target " + std::to_string(static_cast<int>(std::lround(100 * target))) + " %";
    line.x = {*lo / 1.5, *hi * 1.5};
    line.y = {target, target};
    line.dashed = true;
    line.color = "dark-red";
    line.line_width = 1.5;
    p.series.push_back(line);
    return p;
}

}  // namespace

std::vector<std::string> write_eval_plots(const EvalScores& s, const std::string& dir) {
    std::vector<std::string> images;
    // Detection is a_50's own definition: about half the logs at size 1 on seeds that did not measure it.
    for (const auto& image : render_plot(rate_plot(s, "Detected (a verdict other than none), scoring seeds",
                                                   "share of logs detected", &SizeScore::detected, 0.5),
                                         dir, "gap_eval_detected"))
        images.push_back(image);
    for (const auto& image :
         render_plot(rate_plot(s, "Right verdict (top-1; out of library: not attributed), scoring seeds",
                               "share of logs", &SizeScore::top1, 0.8),
                     dir, "gap_eval_top1"))
        images.push_back(image);
    return images;
}

}  // namespace driftlab::host::view
