// Plots through gnuplot: a small description (series, axes, labels) rendered to PNG and/or SVG.
// docs/analysis.md §6.
//
// How to use: fill a Plot (title, axis labels, log scales, one PlotSeries per curve), then call
// render_plot(plot, dir, "name") to get dir/name.png and dir/name.svg, or render_svg(plot) for SVG text to
// inline in HTML. The data and the script are written beside the images (name.dat, name.gp) so a plot can be
// restyled by hand. gnuplot runs as a subprocess; a missing gnuplot is an Error saying how to install it.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace driftlab::host::view {

/// band: the area between y_low and y_high, filled half-transparent (a replicate envelope); y is not drawn.
enum class SeriesStyle { lines, points, dots, steps, error_bars, band };

struct PlotSeries {
    std::string title;  ///< legend entry ("" = none)
    std::vector<double> x, y;
    std::vector<double> y_low, y_high;  ///< for error_bars and band: the ends (same length as y)
    SeriesStyle style = SeriesStyle::lines;
    bool dashed = false;  ///< dotted line, e.g. for bounds
    std::string color;    ///< gnuplot colour name or "#rrggbb"; "" = automatic
    double line_width = 1.5;
};

struct Plot {
    std::string title;
    std::string x_label, y_label;
    bool log_x = false, log_y = false;
    std::optional<std::pair<double, double>> x_range, y_range;
    std::vector<double> x_tics;  ///< explicit x tick positions, labelled as plain numbers (empty = automatic)
    std::vector<std::string> x_tic_labels;  ///< labels of x_tics in their place (empty: the numbers)
    std::string key = "top right";  ///< gnuplot's legend placement, e.g. "outside right top" beside crowded data
    std::vector<PlotSeries> series;
    int width_px = 900, height_px = 540;
};

enum class ImageFormat { png, svg };

/// Renders `plot` into `dir` (created if needed) as name.<format> for each format, every character of `name` other
/// than letters, digits, '_', '-' and '.' written as '_'; returns the image paths.
/// Throws UsageError on an empty or inconsistent plot, Error when gnuplot is missing or fails (with its
/// message).
std::vector<std::string> render_plot(const Plot& plot, const std::string& dir, const std::string& name,
                                     const std::vector<ImageFormat>& formats = {ImageFormat::png, ImageFormat::svg});

/// Every file render_plot(plot, dir, name, formats) writes (its data, scripts, images and passing log), so that a
/// command can refuse an input it would write over before its work.
std::vector<std::string> plot_files(const std::string& dir, const std::string& name,
                                    const std::vector<ImageFormat>& formats = {ImageFormat::png, ImageFormat::svg});

/// The SVG document of `plot` as text (rendered in a temporary folder).
std::string render_svg(const Plot& plot);

/// True when a gnuplot executable is on PATH.
bool gnuplot_available();

}  // namespace driftlab::host::view
