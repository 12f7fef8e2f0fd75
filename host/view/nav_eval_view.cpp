// The views of nav-eval; see nav_eval_view.hpp.
#include "host/view/nav_eval_view.hpp"

#include <cmath>
#include <cstdio>

#include "host/util/format_number.hpp"
#include "host/view/gnuplot.hpp"
#include "host/view/json_out.hpp"
#include "host/view/nav_view.hpp"

namespace driftlab::host::view {
namespace {

using nlohmann::json;

std::string cell(double median, double p95) {
    if (!std::isfinite(median)) return "-";
    return significant_plain(median, 3) + " (" + significant_plain(p95, 3) + ")";
}

}  // namespace

void print_nav_eval_text(std::ostream& out, const NavEvalReport& r) {
    std::string trajectories;
    for (const auto& t : r.trajectories) trajectories += (trajectories.empty() ? "" : ", ") + t;
    std::string aids;
    for (const auto& a : r.aids) aids += (aids.empty() ? "" : ", ") + a;
    out << "nav-eval: " << r.summary.runs << " runs (" << trajectories << "), " << significant_plain(r.duration_s, 6)
        << " s each from power-on, target " << r.target << ", aids: " << (aids.empty() ? "none" : aids)
        << "; process noise: " << r.noise << "\n";
    const auto& s = r.summary;
    char buf[128];
    for (const bool heading : {true, false}) {
        out << (heading ? "heading error [deg]" : "position error [m]") << ", median (95th percentile)\n";
        std::snprintf(buf, sizeof buf, "  %-12s", "variant");
        out << buf;
        for (const double a : s.at_s) {
            std::snprintf(buf, sizeof buf, "  %20s", (significant_plain(a / 60.0, 4) + " min").c_str());
            out << buf;
        }
        out << (heading ? "      drift [deg/min]" : "        [% of distance]") << "\n";
        for (const auto& v : s.variants) {
            std::snprintf(buf, sizeof buf, "  %-12s", v.name.c_str());
            out << buf;
            for (std::size_t k = 0; k < s.at_s.size(); ++k) {
                const std::string c = heading ? cell(v.heading_error_deg[k], v.heading_error_deg_p95[k])
                                              : cell(v.position_error_m[k], v.position_error_m_p95[k]);
                std::snprintf(buf, sizeof buf, "  %20s", c.c_str());
                out << buf;
            }
            const std::string last = heading ? cell(v.heading_drift_deg_per_min, v.heading_drift_deg_per_min_p95)
                                             : cell(v.position_error_pct, v.position_error_pct_p95);
            std::snprintf(buf, sizeof buf, "  %21s\n", last.c_str());
            out << buf;
        }
    }
    out << "pose NEES inside its 95 % band (median share of epochs):";
    for (const auto& v : s.variants)
        out << "  " << v.name << " "
            << (std::isfinite(v.nees_inside_fraction) ? fixed_point(v.nees_inside_fraction, 3) : "-");
    out << "\n";
}

json nav_eval_json(const NavEvalReport& r) {
    json variants = json::object();
    for (const auto& v : r.summary.variants)
        variants[v.name] = {{"heading_error_deg", json_array(v.heading_error_deg)},
                            {"heading_error_deg_p95", json_array(v.heading_error_deg_p95)},
                            {"position_error_m", json_array(v.position_error_m)},
                            {"position_error_m_p95", json_array(v.position_error_m_p95)},
                            {"heading_drift_deg_per_min", json_number(v.heading_drift_deg_per_min)},
                            {"heading_drift_deg_per_min_p95", json_number(v.heading_drift_deg_per_min_p95)},
                            {"position_error_pct", json_number(v.position_error_pct)},
                            {"position_error_pct_p95", json_number(v.position_error_pct_p95)},
                            {"nees_inside_fraction", json_number(v.nees_inside_fraction)}};
    json runs = json::array();
    for (const auto& run : *r.runs) {
        json per = json::object();
        for (const auto& v : run.score.variants)
            per[v.name] = {{"heading_error_deg", json_array(v.heading_error_deg)},
                           {"position_error_m", json_array(v.position_error_m)},
                           {"nees_inside_fraction", json_number(v.nees_inside_fraction)}};
        runs.push_back({{"trajectory", run.trajectory},
                        {"seed", run.seed},
                        {"distance_m", json_number(run.score.distance_m)},
                        {"variants", per}});
    }
    return {{"at_s", r.summary.at_s}, {"runs", r.summary.runs}, {"trajectories", r.trajectories},
            {"target", r.target},     {"aids", r.aids},         {"duration_s", json_number(r.duration_s)},
            {"noise", r.noise},       {"variants", variants},   {"per_run", runs}};
}

void write_nav_eval_plots(const std::string& dir, const NavEvalReport& r) {
    for (const bool heading : {true, false}) {
        Plot p;
        p.title = heading ? "Heading error over the runs" : "Position error over the runs";
        p.x_label = "t [min after power-on]";
        p.y_label = heading ? "|heading error| [deg]: median, bar to the 95th percentile"
                            : "|position error| [m]: median, bar to the 95th percentile";
        p.log_y = true;
        std::vector<double> minutes;
        for (const double a : r.summary.at_s) minutes.push_back(a / 60.0);
        for (std::size_t k = 0; k < r.summary.variants.size(); ++k) {
            const auto& v = r.summary.variants[k];
            const auto& med = heading ? v.heading_error_deg : v.position_error_m;
            const auto& hi = heading ? v.heading_error_deg_p95 : v.position_error_m_p95;
            p.series.push_back(
                {v.name, minutes, med, med, hi, SeriesStyle::error_bars, false, nav_variant_colour(k), 1.5});
            p.series.push_back({"", minutes, med, {}, {}, SeriesStyle::lines, false, nav_variant_colour(k), 1.5});
        }
        render_plot(p, dir, heading ? "nav_eval_heading" : "nav_eval_position");
    }
}

}  // namespace driftlab::host::view
