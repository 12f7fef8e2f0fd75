// `driftlab nav-eval`: navigation scored over many simulated runs (seeds x trajectories, the firmware in the loop),
// each variant's figures as the field reports them: median and 95th percentile over the runs. The runs are made by
// the caller (the command runs the board); this is their summary. docs/nav.md §Monte Carlo.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "host/nav/nav_score.hpp"

namespace driftlab::host::nav {

/// One simulated run and its score.
struct EvalRun {
    std::string trajectory;
    std::uint64_t seed = 0;
    NavScore score;
};

/// A variant over the runs: per evaluation time the median and 95th percentile of the errors (over the runs that
/// reach that time; NaN where none does).
struct EvalVariant {
    std::string name;
    std::vector<double> heading_error_deg, heading_error_deg_p95;
    std::vector<double> position_error_m, position_error_m_p95;
    double heading_drift_deg_per_min = NAN, heading_drift_deg_per_min_p95 = NAN;
    double position_error_pct = NAN, position_error_pct_p95 = NAN;
    double nees_inside_fraction = NAN;  ///< the median over the runs
};

struct EvalSummary {
    std::vector<double> at_s;
    std::vector<EvalVariant> variants;
    std::size_t runs = 0;
};

/// The q-quantile (0..1) of `values` by linear interpolation between order statistics (Hyndman & Fan type 7, numpy's
/// default), NaN values left out; NaN when none is left.
double quantile(std::vector<double> values, double q);

/// The summary of `runs` (each scored with the same variants and times).
EvalSummary summarise(const std::vector<EvalRun>& runs);

}  // namespace driftlab::host::nav
