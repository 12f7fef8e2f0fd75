// What a nav-eval campaign prints once all its runs are scored, whether one process ran them (`nav-eval`) or its
// shards' parts were merged (`merge`): the summary, text or JSON, and plots.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "host/nav/nav_eval.hpp"

namespace driftlab::host::cli {

/// `campaign` as nav-eval states it in a part (trajectories, target, aids, duration_s, effects_noise, ...).
void print_nav_eval(const nlohmann::json& campaign, const std::vector<nav::EvalRun>& runs, bool json,
                    const std::string& plot_dir);

}  // namespace driftlab::host::cli
