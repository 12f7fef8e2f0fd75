// What a gap-eval campaign prints; see gap_eval_output.hpp.
#include "host/cli/gap_eval_output.hpp"

#include <cstdio>
#include <iostream>

#include "host/gap_eval/eval_scores.hpp"
#include "host/view/gap_eval_view.hpp"

namespace driftlab::host::cli {

void print_gap_eval(const gap::EvalOptions& options, const std::vector<gap::DetectionSize>& sizes,
                    const std::vector<gap::EvalCase>& cases, const std::vector<gap::PairCase>& pairs, bool json,
                    const std::string& plot_dir) {
    const gap::Thresholds th = options.tune ? gap::tune(cases) : gap::Thresholds{};
    const gap::EvalScores scores = gap::score(cases, th, options, sizes, pairs);
    // The scores first: a plot that fails must not lose a run of many minutes.
    if (json)
        std::cout << view::scores_json(scores).dump(2) << "\n";
    else
        std::cout << view::scores_markdown(scores);
    std::cout.flush();
    if (!plot_dir.empty()) {
        view::write_eval_plots(scores, plot_dir);
        std::fprintf(stderr, "gap-eval: plots in %s (gap_eval_detected, gap_eval_top1)\n", plot_dir.c_str());
    }
}

}  // namespace driftlab::host::cli
