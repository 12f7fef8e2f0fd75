// The views of a navigation run; see nav_view.hpp.
#include "host/view/nav_view.hpp"

#include <cmath>
#include <cstdio>

#include "host/util/format_number.hpp"
#include "host/util/output_file.hpp"
#include "host/view/gnuplot.hpp"
#include "host/view/json_out.hpp"

namespace driftlab::host::view {
namespace {

using nlohmann::json;

std::string cell(double v, int decimals) { return std::isfinite(v) ? fixed_point(v, decimals) : "-"; }

std::string minutes(double s) { return significant_plain(s / 60.0, 4) + " min"; }

const char* kColours[] = {"#7f7f7f", "#1f77b4", "#ff7f0e", "#2ca02c"};

void print_errors(std::ostream& out, const nav::NavScore& s) {
    std::string head = "variant      ";
    for (const double a : s.at_s) head += "  hdg@" + minutes(a);
    for (const double a : s.at_s) head += "  pos@" + minutes(a);
    out << head << "  drift[deg/min]  pos[% dist]  NEES in 95% band\n";
    char buf[64];
    for (const auto& v : s.variants) {
        std::snprintf(buf, sizeof buf, "%-13s", v.name.c_str());
        out << buf;
        for (std::size_t k = 0; k < s.at_s.size(); ++k) {
            std::snprintf(buf, sizeof buf, "  %*s", static_cast<int>(minutes(s.at_s[k]).size() + 4),
                          cell(v.heading_error_deg[k], 3).c_str());
            out << buf;
        }
        for (std::size_t k = 0; k < s.at_s.size(); ++k) {
            std::snprintf(buf, sizeof buf, "  %*s", static_cast<int>(minutes(s.at_s[k]).size() + 4),
                          cell(v.position_error_m[k], 3).c_str());
            out << buf;
        }
        std::snprintf(buf, sizeof buf, "  %14s  %11s  %16s\n", cell(v.heading_drift_deg_per_min, 4).c_str(),
                      cell(v.position_error_pct, 2).c_str(), cell(v.nees_inside_fraction, 3).c_str());
        out << buf;
    }
    out << "errors are |estimate - truth|: heading [deg] and position [m] at each time after the first row; drift is "
           "the last row's heading error per minute of the run; NEES of the pose (x, y, heading) inside "
           "chi-square(3)'s "
           "two-sided 95 % band\n";
}

}  // namespace

void print_nav_text(std::ostream& out, const NavReport& r) {
    const nav::NavRun& run = *r.run;
    out << r.log_path << ": " << run.t_s.size() << " rows over "
        << significant_plain(run.t_s.back() - run.t_s.front(), 6)
        << " s; drift model: " << (r.drift_source.empty() ? "none" : r.drift_source) << "; aids: ";
    std::string aids;
    for (const auto& a : r.aids) aids += (aids.empty() ? "" : ", ") + a;
    out << (aids.empty() ? "none" : aids) << "; truth: " << (r.truth_source.empty() ? "none" : r.truth_source);
    if (r.score) out << " (" << significant_plain(r.score->distance_m, 5) << " m travelled)";
    out << "\n";
    out << "variant        heading[deg]  sd[deg]       x[m]       y[m]  sd[m]  stops  stood[s]  drift at "
           "stops[deg/min]  "
           "ZUPTs  fixes\n";
    char buf[256];
    for (const nav::Track& t : run.tracks) {
        double stood = 0.0;
        for (const auto& s : t.stops) stood += s.to_s - s.from_s;
        std::snprintf(buf, sizeof buf, "%-13s  %12s  %7s  %9s  %9s  %5s  %5zu  %8s  %23s  %5zu  %5zu\n", t.name.c_str(),
                      cell(t.heading_deg.back(), 3).c_str(), cell(t.heading_sd_deg.back(), 3).c_str(),
                      cell(t.x_m.back(), 3).c_str(), cell(t.y_m.back(), 3).c_str(),
                      cell(t.position_sd_m.back(), 2).c_str(), t.stops.size(), cell(stood, 1).c_str(),
                      cell(nav::heading_drift_at_stops(t, run.t_s), 4).c_str(), t.zero_velocity_updates,
                      t.position_fixes);
        out << buf;
    }
    if (r.score) print_errors(out, *r.score);
    for (const auto& n : run.notes) out << "note: " << n << "\n";
}

json nav_json(const NavReport& r) {
    const nav::NavRun& run = *r.run;
    json variants = json::object();
    for (std::size_t k = 0; k < run.tracks.size(); ++k) {
        const nav::Track& t = run.tracks[k];
        double stood = 0.0;
        json stops = json::array();
        for (const auto& s : t.stops) {
            stood += s.to_s - s.from_s;
            stops.push_back({json_number(s.from_s), json_number(s.to_s)});
        }
        json v = {{"filter", t.filter},
                  {"final",
                   {{"x_m", json_number(t.x_m.back())},
                    {"y_m", json_number(t.y_m.back())},
                    {"heading_deg", json_number(t.heading_deg.back())},
                    {"heading_sd_deg", json_number(t.heading_sd_deg.back())},
                    {"position_sd_m", json_number(t.position_sd_m.back())}}},
                  {"stops", stops},
                  {"stood_s", json_number(stood)},
                  {"heading_drift_at_stops_deg_per_min", json_number(nav::heading_drift_at_stops(t, run.t_s))},
                  {"zero_velocity_updates", t.zero_velocity_updates},
                  {"odometry_updates", t.odometry_updates},
                  {"position_fixes", t.position_fixes}};
        if (r.score) {
            const nav::VariantScore& s = r.score->variants[k];
            v["heading_error_deg"] = json_array(s.heading_error_deg);
            v["position_error_m"] = json_array(s.position_error_m);
            v["heading_drift_deg_per_min"] = json_number(s.heading_drift_deg_per_min);
            v["position_error_pct"] = json_number(s.position_error_pct);
            v["nees_inside_fraction"] = json_number(s.nees_inside_fraction);
        }
        variants[t.name] = v;
    }
    json out = {{"file", r.log_path},
                {"rows", run.t_s.size()},
                {"duration_s", json_number(run.t_s.back() - run.t_s.front())},
                {"drift_model", r.drift_source.empty() ? json(nullptr) : json(r.drift_source)},
                {"aids", r.aids},
                {"truth", r.truth_source.empty() ? json(nullptr) : json(r.truth_source)},
                {"variants", variants},
                {"notes", run.notes}};
    if (r.score) {
        out["at_s"] = r.score->at_s;
        out["distance_m"] = json_number(r.score->distance_m);
        const nav::NeesBand band = nav::pose_nees_band();
        out["nees_band"] = {json_number(band.low), json_number(band.high)};
    }
    return out;
}

void write_nav_estimate_csv(const std::string& path, const nav::NavRun& run) {
    std::string text = "t_s";
    for (const auto& t : run.tracks) text += "," + t.name + ".x_m," + t.name + ".y_m," + t.name + ".heading_deg";
    text += "\n";
    for (std::size_t i = 0; i < run.t_s.size(); ++i) {
        append_double(text, run.t_s[i]);
        for (const auto& t : run.tracks)
            for (const double v : {t.x_m[i], t.y_m[i], t.heading_deg[i]}) {
                text += ',';
                append_double(text, v);
            }
        text += '\n';
    }
    write_output_file(path, text, "estimate");
}

void write_nav_plots(const std::string& dir, const NavReport& r, const std::optional<nav::NavTruth>& truth) {
    const nav::NavRun& run = *r.run;
    std::vector<double> minutes_axis;
    for (const double t : run.t_s) minutes_axis.push_back((t - run.t_s.front()) / 60.0);
    const auto plot = [](const char* title, const char* x, const char* y) {
        Plot p;
        p.title = title, p.x_label = x, p.y_label = y;
        return p;
    };
    Plot heading = plot(truth ? "Heading error per variant" : "Heading per variant", "t [min after the first row]",
                        truth ? "estimate - truth [deg]" : "heading [deg]");
    Plot position = plot("Position error per variant", "t [min after the first row]", "|estimate - truth| [m]");
    Plot path = plot("Trajectory", "x [m]", "y [m]");
    for (std::size_t k = 0; k < run.tracks.size(); ++k) {
        const nav::Track& t = run.tracks[k];
        std::vector<double> dh(t.heading_deg), dp(t.x_m.size());
        for (std::size_t i = 0; truth && i < dh.size(); ++i) {
            dh[i] -= truth->heading_deg(i);
            dp[i] = std::hypot(t.x_m[i] - truth->x(i), t.y_m[i] - truth->y(i));
        }
        const std::string colour = kColours[k % 4];
        heading.series.push_back({t.name, minutes_axis, dh, {}, {}, SeriesStyle::lines, false, colour, 1.5});
        position.series.push_back({t.name, minutes_axis, dp, {}, {}, SeriesStyle::lines, false, colour, 1.5});
        path.series.push_back({t.name, t.x_m, t.y_m, {}, {}, SeriesStyle::lines, false, colour, 1.5});
    }
    render_plot(heading, dir, "nav_heading");
    if (!truth) return;
    std::vector<double> tx, ty;
    for (std::size_t i = 0; i < run.t_s.size(); ++i) tx.push_back(truth->x(i)), ty.push_back(truth->y(i));
    path.series.push_back({"truth", tx, ty, {}, {}, SeriesStyle::lines, true, "#d62728", 2.0});
    render_plot(position, dir, "nav_position_error");
    render_plot(path, dir, "nav_trajectory");
}

}  // namespace driftlab::host::view
