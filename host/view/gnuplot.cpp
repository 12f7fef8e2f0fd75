// gnuplot rendering; see gnuplot.hpp.
#include "host/view/gnuplot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/output_folder.hpp"

extern char** environ;

namespace driftlab::host::view {
namespace {

namespace fs = std::filesystem;

/// gnuplot string literal: single quotes, with a quote doubled.
std::string quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) {
        if (c == '\'') out += '\'';
        out += c;
    }
    return out + "'";
}

bool has_ends(const PlotSeries& s) { return s.style == SeriesStyle::error_bars || s.style == SeriesStyle::band; }

void check(const Plot& plot) {
    if (plot.series.empty()) throw UsageError("plot '" + plot.title + "' has no series");
    for (const auto& s : plot.series) {
        if (s.x.size() != s.y.size()) throw UsageError("plot series '" + s.title + "': x and y differ in length");
        if (has_ends(s) && (s.y_low.size() != s.y.size() || s.y_high.size() != s.y.size()))
            throw UsageError("plot series '" + s.title +
                             "': error bars and bands need y_low and y_high for every point");
    }
}

/// One data block per series, separated by two blank lines (gnuplot's `index`). Non-finite values become
/// "NaN", which gnuplot skips.
void write_data(const Plot& plot, const fs::path& path) {
    std::string text;
    for (const auto& s : plot.series) {
        for (std::size_t i = 0; i < s.x.size(); ++i) {
            const auto put = [&](double v) {
                if (std::isfinite(v))
                    append_double(text, v);
                else
                    text += "NaN";
            };
            put(s.x[i]);
            text += ' ';
            put(s.y[i]);
            if (has_ends(s)) {
                text += ' ';
                put(s.y_low[i]);
                text += ' ';
                put(s.y_high[i]);
            }
            text += '\n';
        }
        text += "\n\n";
    }
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) throw DeviceError(path.string(), "cannot write plot data");
}

std::string style_clause(const PlotSeries& s) {
    std::string clause;
    switch (s.style) {
    case SeriesStyle::lines: clause = "with lines"; break;
    case SeriesStyle::points: clause = "with points pt 7 ps 0.5"; break;
    case SeriesStyle::dots: clause = "with dots"; break;
    case SeriesStyle::steps: clause = "with steps"; break;
    case SeriesStyle::error_bars: clause = "with yerrorbars pt 7 ps 0.6"; break;
    case SeriesStyle::band: clause = "with filledcurves fs transparent solid 0.25 noborder"; break;
    }
    clause += " lw " + format_double(s.line_width);
    if (s.dashed) clause += " dt 3";
    if (!s.color.empty()) clause += " lc rgb " + quoted(s.color);
    clause += s.title.empty() ? " notitle" : " title " + quoted(s.title) + " noenhanced";  // names hold underscores
    return clause;
}

std::string script(const Plot& plot, const fs::path& data, const fs::path& image, ImageFormat format) {
    std::ostringstream gp;
    const std::string size = std::to_string(plot.width_px) + "," + std::to_string(plot.height_px);
    if (format == ImageFormat::png)
        gp << "set terminal pngcairo size " << size << " enhanced font 'sans,10'\n";
    else
        gp << "set terminal svg size " << size << " dynamic enhanced font 'sans,10' background rgb 'white'\n";
    gp << "set output " << quoted(image.string()) << "\n";
    gp << "set encoding utf8\nset grid\nset key " << plot.key << "\n";
    gp << "set title " << quoted(plot.title) << " noenhanced\n";
    gp << "set xlabel " << quoted(plot.x_label) << " noenhanced\n";
    gp << "set ylabel " << quoted(plot.y_label) << " noenhanced\n";
    if (plot.log_x) gp << "set logscale x\n" << (plot.x_tics.empty() ? "set format x '10^{%L}'\n" : "");
    if (!plot.x_tics.empty()) {
        gp << "set xtics (";
        for (std::size_t i = 0; i < plot.x_tics.size(); ++i)
            gp << (i ? ", " : "") << (i < plot.x_tic_labels.size() ? quoted(plot.x_tic_labels[i]) + " " : "")
               << format_double(plot.x_tics[i]);
        gp << ")\n";
    }
    if (plot.log_y) gp << "set logscale y\nset format y '10^{%L}'\n";
    if (plot.x_range)
        gp << "set xrange [" << format_double(plot.x_range->first) << ":" << format_double(plot.x_range->second)
           << "]\n";
    if (plot.y_range)
        gp << "set yrange [" << format_double(plot.y_range->first) << ":" << format_double(plot.y_range->second)
           << "]\n";
    gp << "plot ";
    for (std::size_t i = 0; i < plot.series.size(); ++i) {
        const auto& s = plot.series[i];
        if (i) gp << ", \\\n     ";
        const char* columns = s.style == SeriesStyle::error_bars ? " using 1:2:3:4 "
                              : s.style == SeriesStyle::band     ? " using 1:3:4 "
                                                                 : " using 1:2 ";
        gp << quoted(data.string()) << " index " << i << columns << style_clause(s);
    }
    gp << "\nunset output\n";
    return gp.str();
}

/// Runs `gnuplot script`, stdout and stderr to `log`. Throws with gnuplot's message when it fails.
void run_gnuplot(const fs::path& script_path, const fs::path& log_path) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    std::string prog = "gnuplot";
    std::string arg = script_path.string();
    char* argv[] = {prog.data(), arg.data(), nullptr};
    pid_t pid = 0;
    const int rc = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0)
        throw Error(std::string("cannot run gnuplot (") + std::strerror(rc) +
                    "): install it (Debian: gnuplot-nox, see scripts/setup.sh) or leave out --plot");
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::ifstream in(log_path);
        std::stringstream msg;
        msg << in.rdbuf();
        if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
            throw Error("gnuplot not found on PATH: install it (Debian: gnuplot-nox) or leave out --plot");
        throw Error("gnuplot failed on " + script_path.string() + ": " + msg.str());
    }
}

}  // namespace

bool gnuplot_available() {
    const char* path = std::getenv("PATH");
    if (!path) return false;
    std::stringstream dirs(path);
    std::string dir;
    while (std::getline(dirs, dir, ':'))
        if (!dir.empty() && ::access((fs::path(dir) / "gnuplot").c_str(), X_OK) == 0) return true;
    return false;
}

namespace {

// Every file render_plot() writes for one plot: one place for their names, which plot_files() lists.
struct PlotPaths {
    fs::path data, log;
    std::vector<std::pair<fs::path, fs::path>> images;  ///< per format: the image and its script
};

PlotPaths plot_paths(const std::string& dir, const std::string& name, const std::vector<ImageFormat>& formats) {
    // The name comes from a column header ("gyro(deg/s)", "a/b"): only characters safe in a file name are kept.
    std::string file_name = name;
    for (char& c : file_name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') c = '_';
    const std::string base = (fs::path(dir) / file_name).string();
    PlotPaths p{base + ".dat", base + ".gnuplot.log", {}};
    for (ImageFormat f : formats) {
        const std::string image = base + (f == ImageFormat::png ? ".png" : ".svg");
        p.images.emplace_back(image, image + ".gp");
    }
    return p;
}

}  // namespace

std::vector<std::string> plot_files(const std::string& dir, const std::string& name,
                                    const std::vector<ImageFormat>& formats) {
    const PlotPaths p = plot_paths(dir, name, formats);
    std::vector<std::string> out{p.data.string(), p.log.string()};
    for (const auto& [image, gp] : p.images) out.insert(out.end(), {image.string(), gp.string()});
    return out;
}

std::vector<std::string> render_plot(const Plot& plot, const std::string& dir, const std::string& name,
                                     const std::vector<ImageFormat>& formats) {
    check(plot);
    make_output_folder(dir, "plot");
    const PlotPaths p = plot_paths(dir, name, formats);
    write_data(plot, p.data);
    std::vector<std::string> images;
    for (std::size_t k = 0; k < formats.size(); ++k) {
        const auto& [image, gp] = p.images[k];
        std::ofstream(gp, std::ios::binary) << script(plot, p.data, image, formats[k]);
        run_gnuplot(gp, p.log);
        images.push_back(image.string());
    }
    std::error_code ec;  // a log left behind is harmless
    fs::remove(p.log, ec);
    return images;
}

std::string render_svg(const Plot& plot) {
    std::random_device rd;
    const fs::path dir =
        fs::temp_directory_path() / ("driftlab_plot_" + std::to_string(::getpid()) + "_" + std::to_string(rd()));
    std::string svg;
    try {
        const auto images = render_plot(plot, dir.string(), "plot", {ImageFormat::svg});
        std::ifstream in(images.front(), std::ios::binary);
        std::stringstream s;
        s << in.rdbuf();
        svg = s.str();
    } catch (...) {
        std::error_code ec;
        fs::remove_all(dir, ec);
        throw;
    }
    std::error_code ec;
    fs::remove_all(dir, ec);
    return svg;
}

}  // namespace driftlab::host::view
