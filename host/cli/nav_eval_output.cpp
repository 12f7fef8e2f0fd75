// What a nav-eval campaign prints; see nav_eval_output.hpp.
#include "host/cli/nav_eval_output.hpp"

#include <iostream>

#include "host/view/json_out.hpp"
#include "host/view/nav_eval_view.hpp"

namespace driftlab::host::cli {

void print_nav_eval(const nlohmann::json& campaign, const std::vector<nav::EvalRun>& runs, bool json,
                    const std::string& plot_dir) {
    const std::string noise = campaign.at("effects_noise").get<bool>()
                                  ? "the rest log's Allan terms and the model's bias effects"
                                  : "the rest log's Allan terms";
    const view::NavEvalReport report{campaign.at("trajectories").get<std::vector<std::string>>(),
                                     campaign.at("target").get<std::string>(),
                                     campaign.at("aids").get<std::vector<std::string>>(),
                                     campaign.at("duration_s").get<double>(),
                                     noise,
                                     &runs,
                                     nav::summarise(runs)};
    if (json)
        view::write_json(std::cout, view::nav_eval_json(report));
    else
        view::print_nav_eval_text(std::cout, report);
    if (!plot_dir.empty()) view::write_nav_eval_plots(plot_dir, report);
}

}  // namespace driftlab::host::cli
