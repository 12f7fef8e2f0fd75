// The views of a navigation run (`driftlab nav`, docs/nav.md): a table per variant, JSON, every variant's estimate
// as CSV, and plots (heading and position error against time, the trajectory against the truth).
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "host/nav/nav_score.hpp"
#include "host/nav/navigate.hpp"

namespace driftlab::host::view {

/// What a run was, beside its result.
struct NavReport {
    std::string log_path;
    std::string drift_source;       ///< "" without a drift model
    std::vector<std::string> aids;  ///< the aids asked for
    std::string truth_source;       ///< "" without a truth; "at rest" for --at-rest
    const nav::NavRun* run = nullptr;
    std::optional<nav::NavScore> score;  ///< with a truth
};

void print_nav_text(std::ostream& out, const NavReport& r);
nlohmann::json nav_json(const NavReport& r);
/// `t_s`, then `<variant>.x_m`, `<variant>.y_m`, `<variant>.heading_deg` per variant, a row per log row.
void write_nav_estimate_csv(const std::string& path, const nav::NavRun& run);
/// nav_heading.png/svg (and nav_trajectory, nav_position_error with a truth) into `dir`.
void write_nav_plots(const std::string& dir, const NavReport& r, const std::optional<nav::NavTruth>& truth);

}  // namespace driftlab::host::view
