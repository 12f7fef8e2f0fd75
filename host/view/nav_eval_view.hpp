// The views of `driftlab nav-eval` (docs/nav.md §Monte Carlo): a table per variant, JSON sharing nav --json's keys
// (at_s; variants.<name>.heading_error_deg[], position_error_m[], nees_inside_fraction), and a plot of the errors
// against time.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "host/nav/nav_eval.hpp"

namespace driftlab::host::view {

struct NavEvalReport {
    std::vector<std::string> trajectories;
    std::string target;
    std::vector<std::string> aids;
    double duration_s = 0.0;
    std::string noise;  ///< where the filters' process noise came from
    const std::vector<nav::EvalRun>* runs = nullptr;
    nav::EvalSummary summary;
};

void print_nav_eval_text(std::ostream& out, const NavEvalReport& r);
nlohmann::json nav_eval_json(const NavEvalReport& r);
/// nav_eval_heading.png/svg and nav_eval_position.png/svg: medians with the 95th percentile, per variant.
void write_nav_eval_plots(const std::string& dir, const NavEvalReport& r);

}  // namespace driftlab::host::view
