// The report's navigation section; see nav_section.hpp.
#include "host/view/nav_section.hpp"

#include "host/util/error.hpp"
#include "host/view/html.hpp"

namespace driftlab::host::view {
namespace {

using nlohmann::json;

double number(const json& j) { return j.is_number() ? j.get<double>() : NAN; }

std::string scores_table(const json& nav) {
    const auto& at = nav["at_s"];
    std::string h = "<table><tr><th>variant</th>";
    for (const auto& a : at) h += "<th>heading error at " + sig(number(a) / 60.0, 3) + " min [&deg;]</th>";
    for (const auto& a : at) h += "<th>position error at " + sig(number(a) / 60.0, 3) + " min [m]</th>";
    h += "<th>drift [&deg;/min]</th><th>position error [% of distance]</th><th>NEES inside its 95 % band</th></tr>\n";
    for (const auto& [name, v] : nav["variants"].items()) {
        h += "<tr><td>" + html_escape(name) + "</td>";
        for (std::size_t k = 0; k < at.size(); ++k) h += "<td>" + sig(number(v["heading_error_deg"][k]), 3) + "</td>";
        for (std::size_t k = 0; k < at.size(); ++k) h += "<td>" + sig(number(v["position_error_m"][k]), 3) + "</td>";
        h += "<td>" + sig(number(v["heading_drift_deg_per_min"]), 3) + "</td><td>" +
             sig(number(v["position_error_pct"]), 3) + "</td><td>" + fixed(number(v["nees_inside_fraction"]), 3) +
             "</td></tr>\n";
    }
    return h + "</table>\n";
}

std::string finals_table(const json& nav) {
    std::string h =
        "<table><tr><th>variant</th><th>final heading [&deg;]</th><th>&sigma; [&deg;]</th><th>x [m]</th>"
        "<th>y [m]</th><th>stops</th><th>stood [s]</th><th>heading drift at stops [&deg;/min]</th></tr>\n";
    for (const auto& [name, v] : nav["variants"].items()) {
        const json& f = v["final"];
        h += "<tr><td>" + html_escape(name) + "</td><td>" + sig(number(f["heading_deg"]), 4) + "</td><td>" +
             sig(number(f["heading_sd_deg"]), 3) + "</td><td>" + sig(number(f["x_m"]), 4) + "</td><td>" +
             sig(number(f["y_m"]), 4) + "</td><td>" + std::to_string(v["stops"].size()) + "</td><td>" +
             sig(number(v["stood_s"]), 4) + "</td><td>" + sig(number(v["heading_drift_at_stops_deg_per_min"]), 3) +
             "</td></tr>\n";
    }
    return h + "</table>\n";
}

}  // namespace

NavSection nav_section(const json& nav, const std::string& path) {
    if (!nav.is_object() || !nav.contains("variants") || !nav["variants"].is_object() || !nav.contains("series") ||
        !nav.contains("file"))
        throw DataError(path, 0, "not what nav --json prints (file, variants, series)");
    for (const auto& [name, v] : nav["variants"].items())
        if (!v.contains("final") || !v.contains("stops"))
            throw DataError(path, 0, "variants." + name + ": no final pose or stops (is this nav --json's output?)");
    NavSection s;
    const bool scored = nav.contains("at_s");
    s.html = "<h2>Navigation</h2>\n<p>Log <code>" + html_escape(nav["file"].get<std::string>()) + "</code>, " +
             std::to_string(nav.value("rows", 0)) + " rows over " + sig(number(nav["duration_s"]), 5) +
             " s; drift model: " +
             html_escape(nav["drift_model"].is_string() ? nav["drift_model"].get<std::string>() : "none") +
             "; truth: " + html_escape(nav["truth"].is_string() ? nav["truth"].get<std::string>() : "none") +
             (scored ? " (" + sig(number(nav["distance_m"]), 5) + " m travelled)" : "") + ". From <code>" +
             html_escape(path) + "</code> (docs/nav.md).</p>\n";
    s.html += finals_table(nav);
    if (scored) s.html += scores_table(nav);
    for (const auto& n : nav.value("notes", json::array()))
        s.html += "<p>Note: " + html_escape(n.get<std::string>()) + "</p>\n";
    s.plots = nav_plots(nav_curves_from_json(nav["series"], path));
    return s;
}

}  // namespace driftlab::host::view
