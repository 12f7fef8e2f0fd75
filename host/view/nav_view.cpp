// The views of a navigation run; see nav_view.hpp.
#include "host/view/nav_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/output_file.hpp"
#include "host/view/gnuplot.hpp"
#include "host/view/json_out.hpp"

namespace driftlab::host::view {
namespace {

using nlohmann::json;

std::string cell(double v, int decimals) { return std::isfinite(v) ? fixed_point(v, decimals) : "-"; }

std::string minutes(double s) { return significant_plain(s / 60.0, 4) + " min"; }

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
           "the last row's heading error per minute of the run; NEES of the "
        << (s.nees_dof == 1 ? "heading" : "pose (x, y, heading)") << " inside chi-square(" << s.nees_dof
        << ")'s two-sided 95 % band\n";
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
                {"notes", run.notes},
                {"series", nav_curves_json(r.curves)}};
    if (r.score) {
        out["at_s"] = r.score->at_s;
        out["distance_m"] = json_number(r.score->distance_m);
        const nav::NeesBand band = nav::nees_band(r.score->nees_dof);
        out["nees_band"] = {json_number(band.low), json_number(band.high)};
        out["nees_dof"] = r.score->nees_dof;
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

NavCurves nav_curves(const nav::NavRun& run, const std::optional<nav::NavTruth>& truth, std::size_t max_points) {
    NavCurves c;
    const std::size_t n = run.t_s.size();
    const std::size_t step = std::max<std::size_t>(1, (n + max_points - 1) / std::max<std::size_t>(max_points, 1));
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < n; i += step) rows.push_back(i);
    if (rows.back() != n - 1) rows.push_back(n - 1);
    for (const std::size_t i : rows) c.t_s.push_back(run.t_s[i]);
    if (truth) {
        c.truth.emplace();
        for (const std::size_t i : rows) {
            c.truth->x_m.push_back(truth->x(i));
            c.truth->y_m.push_back(truth->y(i));
            c.truth->heading_deg.push_back(truth->heading_deg(i));
        }
    }
    for (const nav::Track& t : run.tracks) {
        NavCurves::Pose p;
        for (const std::size_t i : rows) {
            p.x_m.push_back(t.x_m[i]);
            p.y_m.push_back(t.y_m[i]);
            p.heading_deg.push_back(t.heading_deg[i]);
        }
        c.variants.emplace_back(t.name, std::move(p));
    }
    return c;
}

namespace {

json pose_json(const NavCurves::Pose& p) {
    return {{"x_m", json_array(p.x_m)}, {"y_m", json_array(p.y_m)}, {"heading_deg", json_array(p.heading_deg)}};
}

NavCurves::Pose pose_from_json(const json& j, const std::string& path, const std::string& what) {
    NavCurves::Pose p;
    try {
        p.x_m = j.at("x_m").get<std::vector<double>>();
        p.y_m = j.at("y_m").get<std::vector<double>>();
        p.heading_deg = j.at("heading_deg").get<std::vector<double>>();
    } catch (const json::exception&) {
        throw DataError(path, 0, "series." + what + ": not the x_m, y_m and heading_deg arrays nav --json writes");
    }
    return p;
}

}  // namespace

json nav_curves_json(const NavCurves& c) {
    json variants = json::object();
    for (const auto& [name, pose] : c.variants) variants[name] = pose_json(pose);
    return {
        {"t_s", json_array(c.t_s)}, {"truth", c.truth ? pose_json(*c.truth) : json(nullptr)}, {"variants", variants}};
}

NavCurves nav_curves_from_json(const json& series, const std::string& path) {
    NavCurves c;
    if (!series.is_object() || !series.contains("t_s") || !series.contains("variants"))
        throw DataError(path, 0, "no 'series' of nav --json (t_s, variants)");
    c.t_s = series["t_s"].get<std::vector<double>>();
    if (series.contains("truth") && !series["truth"].is_null())
        c.truth = pose_from_json(series["truth"], path, "truth");
    for (const auto& [name, pose] : series["variants"].items())
        c.variants.emplace_back(name, pose_from_json(pose, path, "variants." + name));
    for (const auto& v : c.variants)
        if (v.second.x_m.size() != c.t_s.size())
            throw DataError(path, 0, "series." + v.first + ": not one value per t_s");
    if (c.truth && c.truth->x_m.size() != c.t_s.size()) throw DataError(path, 0, "series.truth: not one value per t_s");
    return c;
}

std::vector<NamedPlot> nav_plots(const NavCurves& c) {
    std::vector<double> minutes_axis;
    for (const double t : c.t_s) minutes_axis.push_back((t - c.t_s.front()) / 60.0);
    const auto plot = [](const char* title, const char* x, const char* y) {
        Plot p;
        p.title = title, p.x_label = x, p.y_label = y;
        return p;
    };
    const bool truth = c.truth.has_value();
    // With a truth the errors span decades between the variants: |error| on a log scale, from 0.0001 deg.
    Plot heading = plot(truth ? "Heading error per variant" : "Heading per variant", "t [min after the first row]",
                        truth ? "|estimate - truth| [deg]" : "heading [deg]");
    heading.log_y = truth;
    Plot position = plot("Position error per variant", "t [min after the first row]", "|estimate - truth| [m]");
    position.log_y = true;
    Plot path = plot("Trajectory", "x [m]", "y [m]");
    for (std::size_t k = 0; k < c.variants.size(); ++k) {
        const auto& [name, p] = c.variants[k];
        std::vector<double> dh(p.heading_deg), dp(p.x_m.size());
        for (std::size_t i = 0; truth && i < dh.size(); ++i) {
            dh[i] = std::max(std::abs(dh[i] - c.truth->heading_deg[i]), 1e-4);
            dp[i] = std::max(std::hypot(p.x_m[i] - c.truth->x_m[i], p.y_m[i] - c.truth->y_m[i]), 1e-4);
        }
        const std::string colour = nav_variant_colour(k);
        heading.series.push_back({name, minutes_axis, dh, {}, {}, SeriesStyle::lines, false, colour, 1.5});
        position.series.push_back({name, minutes_axis, dp, {}, {}, SeriesStyle::lines, false, colour, 1.5});
        path.series.push_back({name, p.x_m, p.y_m, {}, {}, SeriesStyle::lines, false, colour, 1.5});
    }
    std::vector<NamedPlot> out = {{"nav_heading", heading}};
    if (!truth) return out;
    path.series.push_back({"truth", c.truth->x_m, c.truth->y_m, {}, {}, SeriesStyle::lines, true, "#d62728", 2.0});
    // Framed on the truth: a variant kilometres off leaves the frame rather than shrink the path to a dot.
    const auto frame = [](const std::vector<double>& v) {
        const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
        const double margin = std::max(0.25 * (*hi - *lo), 1.0);
        return std::make_pair(*lo - margin, *hi + margin);
    };
    path.x_range = frame(c.truth->x_m);
    path.y_range = frame(c.truth->y_m);
    path.title = "Trajectory, framed on the truth";
    out.push_back({"nav_position_error", position});
    out.push_back({"nav_trajectory", path});
    return out;
}

void write_nav_plots(const std::string& dir, const NavCurves& curves) {
    for (const NamedPlot& p : nav_plots(curves)) render_plot(p.plot, dir, p.name);
}

}  // namespace driftlab::host::view
