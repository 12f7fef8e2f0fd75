// Helpers shared by the host-in-the-loop tests: run a preset into memory, column statistics.
#pragma once

#include <cmath>
#include <vector>

#include "sim/hil/hil.hpp"
#include "sim/hil/hil_preset.hpp"
#include "sim/model/model_file.hpp"

namespace driftlab::sim::testing {

struct Run {
    HilSummary summary;
    std::vector<HilRecord> rows;
};

inline Run run_into_memory(const HilOptions& options) {
    Run r;
    r.summary = run_hil(options, [&](const HilRecord& rec) { r.rows.push_back(rec); });
    return r;
}

inline HilOptions preset(Preset p, std::uint64_t seed = 1) {
    HilOptions o;
    o.model = paper_model();
    o.seed = seed;
    apply_preset(p, o);
    return o;
}

/// Sample standard deviation (n - 1).
inline double stddev(const std::vector<double>& x) {
    double mean = 0.0;
    for (double v : x) mean += v;
    mean /= static_cast<double>(x.size());
    double ss = 0.0;
    for (double v : x) ss += (v - mean) * (v - mean);
    return std::sqrt(ss / static_cast<double>(x.size() - 1));
}

}  // namespace driftlab::sim::testing
