// What the gap-eval tests share: a short run's options and a count of the planted cases named right.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "host/gap_eval/thresholds.hpp"

namespace driftlab::host::gap {

// A short run: one tuning seed, three scoring seeds, strong effects only, few replicates.
inline EvalOptions quick_options() {
    EvalOptions o;
    o.tune_first = 1;
    o.tune_last = 1;
    o.score_first = 11;
    o.score_last = 13;
    o.generators = {"thermal_rc", "burst_spikes"};
    o.levels = {4.0};
    o.samples = 1200;
    o.replicates = 16;
    o.fit_replicates = 6;
    o.max_evaluations = 10;
    return o;
}

// Of the planted (not clean) cases, how many there are and how many decide() names `effect`.
inline std::pair<int, int> planted_and_right(const std::vector<EvalCase>& cases, const std::string& effect) {
    int planted = 0, right = 0;
    for (const auto& c : cases) {
        if (c.generator == "none") continue;
        ++planted;
        right += decide(c, Thresholds{}).verdict == effect;
    }
    return {planted, right};
}

}  // namespace driftlab::host::gap
