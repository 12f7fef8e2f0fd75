// What a gap-eval campaign prints once all its logs are diagnosed, whether one process ran them (`gap-eval`) or its
// shards' parts were merged (`merge`): thresholds tuned (or shipped), scores, markdown or JSON, plots.
#pragma once

#include <string>
#include <vector>

#include "host/gap_eval/evaluate.hpp"

namespace driftlab::host::cli {

void print_gap_eval(const gap::EvalOptions& options, const std::vector<gap::DetectionSize>& sizes,
                    const std::vector<gap::EvalCase>& cases, const std::vector<gap::PairCase>& pairs, bool json,
                    const std::string& plot_dir);

}  // namespace driftlab::host::cli
