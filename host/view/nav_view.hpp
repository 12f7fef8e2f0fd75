// The views of a navigation run (`driftlab nav`, docs/nav.md): a table per variant, JSON, every variant's estimate
// as CSV, and plots (heading and position error against time, the trajectory against the truth).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "host/nav/nav_score.hpp"
#include "host/nav/navigate.hpp"
#include "host/view/gnuplot.hpp"

namespace driftlab::host::view {

/// Each variant's colour in every navigation plot (nav, nav-eval, the report), in the variants' order.
inline constexpr std::array<const char*, 4> kNavVariantColours = {"#7f7f7f", "#1f77b4", "#ff7f0e", "#2ca02c"};
inline const char* nav_variant_colour(std::size_t k) { return kNavVariantColours[k % kNavVariantColours.size()]; }

/// A run's curves as its plots draw them: the rows' times, the truth's pose (in the frame of the first row, when
/// known) and each variant's, at up to a given number of rows (the first, every k-th, the last).
struct NavCurves {
    struct Pose {
        std::vector<double> x_m, y_m, heading_deg;
    };
    std::vector<double> t_s;
    std::optional<Pose> truth;
    std::vector<std::pair<std::string, Pose>> variants;
};
NavCurves nav_curves(const nav::NavRun& run, const std::optional<nav::NavTruth>& truth, std::size_t max_points);

/// What a run was, beside its result.
struct NavReport {
    std::string log_path;
    std::string drift_source;       ///< "" without a drift model
    std::vector<std::string> aids;  ///< the aids asked for
    std::string truth_source;       ///< "" without a truth; "at rest" for --at-rest
    const nav::NavRun* run = nullptr;
    std::optional<nav::NavScore> score;  ///< with a truth
    NavCurves curves;                    ///< JSON's `series`: the run at up to kNavJsonPoints rows
};

/// The rows nav --json's `series` holds at most: enough for a report's figures, small beside the log.
inline constexpr std::size_t kNavJsonPoints = 2000;

void print_nav_text(std::ostream& out, const NavReport& r);
nlohmann::json nav_json(const NavReport& r);
/// `t_s`, then `<variant>.x_m`, `<variant>.y_m`, `<variant>.heading_deg` per variant, a row per log row.
void write_nav_estimate_csv(const std::string& path, const nav::NavRun& run);
/// nav --json's `series`, and back (DataError naming `path` where it is not that).
nlohmann::json nav_curves_json(const NavCurves& c);
NavCurves nav_curves_from_json(const nlohmann::json& series, const std::string& path);

struct NamedPlot {
    std::string name;
    Plot plot;
};
/// nav_heading (heading error with a truth, else heading), and with a truth nav_position_error and nav_trajectory.
std::vector<NamedPlot> nav_plots(const NavCurves& c);
/// nav_plots() as PNG and SVG into `dir`.
void write_nav_plots(const std::string& dir, const NavCurves& curves);

}  // namespace driftlab::host::view
