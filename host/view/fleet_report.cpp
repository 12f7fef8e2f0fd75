// The plots and the markdown report of a fleet; see fleet_view.hpp.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/output_folder.hpp"
#include "host/view/fleet_view.hpp"
#include "host/view/gnuplot.hpp"

namespace driftlab::host::view {

using fleet::kParameters;

namespace {

// Every judged parameter of `channel` at x = its place, the boards spread across +-0.3 of it; the boards that stand
// out for that parameter in red.
Plot channel_plot(const FleetView& v, const std::string& channel) {
    Plot p;
    p.title = "fleet: " + channel + ", each board against the batch";
    p.x_label = "parameter";
    p.y_label = "robust z-score (boards spread left to right in the fleet's order)";
    p.key = "outside right top";
    p.width_px = 1000;
    PlotSeries usual{"boards", {}, {}, {}, {}, SeriesStyle::points, false, "#1f77b4"};
    PlotSeries outlying{"stands out", {}, {}, {}, {}, SeriesStyle::points, false, "#d62728"};
    const double n = static_cast<double>(std::max<std::size_t>(v.boards->size(), 2) - 1);
    for (const fleet::Distribution& d : v.batch.distributions) {
        if (d.channel != channel || d.z.empty()) continue;
        const double x = static_cast<double>(d.parameter + 1);
        p.x_tics.push_back(x);
        p.x_tic_labels.push_back(kParameters[d.parameter].name);
        for (std::size_t i = 0; i < d.z.size(); ++i) {
            const double at = x - 0.3 + 0.6 * static_cast<double>(d.judged_boards[i]) / n;
            PlotSeries& s = std::fabs(d.z[i]) > d.limit ? outlying : usual;
            s.x.push_back(at);
            s.y.push_back(d.z[i]);
        }
    }
    p.x_range = std::make_pair(0.5, static_cast<double>(fleet::kParameterCount) + 0.5);
    p.series.push_back(usual);
    if (!outlying.x.empty()) p.series.push_back(outlying);
    PlotSeries limits{"limit", {}, {}, {}, {}, SeriesStyle::lines, true, "#555555"};
    for (const fleet::Distribution& d : v.batch.distributions) {
        if (d.channel != channel || d.z.empty()) continue;
        const double x = static_cast<double>(d.parameter + 1);
        // Each parameter's limit above and below it; NaN breaks the line between them.
        for (const double sign : {1.0, -1.0}) {
            limits.x.insert(limits.x.end(), {x - 0.4, x + 0.4, x});
            limits.y.insert(limits.y.end(), {sign * d.limit, sign * d.limit, NAN});
        }
    }
    p.series.push_back(limits);
    return p;
}

std::vector<std::string> judged_channels(const FleetView& v) {
    std::vector<std::string> out;
    for (const fleet::Distribution& d : v.batch.distributions)
        if (!d.z.empty() && std::find(out.begin(), out.end(), d.channel) == out.end()) out.push_back(d.channel);
    return out;
}

void write_boards(std::ostream& md, const FleetView& v) {
    md << "## Boards\n\n| log | channel | C1 [counts] | C2 [counts] | T [s] | N | B | K | gap |\n"
       << "|---|---|---|---|---|---|---|---|---|\n";
    for (const fleet::BoardEntry& b : *v.boards) {
        if (!b.result) continue;
        for (std::size_t c = 0; c < b.result->channels.size(); ++c) {
            md << "| " << b.log << " | " << b.result->channels[c].channel;
            for (const std::string& cell : channel_cells(*b.result, c, "±", "–")) md << " | " << cell;
            md << " |\n";
        }
    }
}

void write_batch(std::ostream& md, const FleetView& v) {
    md << "\n## Batch\n\nMedian and robust spread (1.4826 × the median absolute deviation; ×/ a factor for "
          "parameters compared on a log scale) over the boards whose log determines the value.\n\n"
       << "| channel | parameter | unit | boards | median | spread | range |\n|---|---|---|---|---|---|---|\n";
    for (const fleet::Distribution& d : v.batch.distributions)
        md << "| " << d.channel << " | " << kParameters[d.parameter].name << " | " << kParameters[d.parameter].unit
           << " | " << d.boards << " | " << significant_plain(d.median, 5) << " | " << spread_cell(d, "×/") << " | "
           << significant_plain(d.low, 4) << " – " << significant_plain(d.high, 4) << " |\n";
}

}  // namespace

std::vector<std::string> write_fleet_plots(const FleetView& v, const std::string& dir) {
    std::vector<std::string> names;
    for (const std::string& channel : judged_channels(v)) {
        render_plot(channel_plot(v, channel), dir, "fleet_" + channel);
        names.push_back("fleet_" + channel);
    }
    return names;
}

void write_fleet_report(const FleetView& v, const std::string& dir) {
    const std::vector<std::string> figures =
        gnuplot_available() ? write_fleet_plots(v, dir) : std::vector<std::string>{};
    std::ofstream md(dir + "/fleet.md");
    md << "# Fleet of " << counted(v.batch.boards, "log") << "\n\n" << v.batch.analysed << " boards analysed.\n\n";
    md << "## Boards that stand out\n\n";
    if (v.batch.standouts.empty())
        md << "None: every value within its limit of robust spreads from the batch, every analysis done.\n";
    for (const fleet::Standout& s : v.batch.standouts)
        md << "- " << (*v.boards)[s.board].log << ": " << s.reason << "\n";
    for (const fleet::BoardEntry& b : *v.boards)
        if (!b.result) md << "- not analysed: " << b.error << "\n";
    if (!v.batch.verdicts.empty()) md << "\nGap verdicts: " << verdict_summary(v) << ".\n";
    md << "\n";
    for (const std::string& f : figures) md << "![" << f << "](" << f << ".svg)\n\n";
    write_boards(md, v);
    write_batch(md, v);
    md.close();
    if (!md) throw DeviceError(dir + "/fleet.md", "cannot write the report");
}

}  // namespace driftlab::host::view
