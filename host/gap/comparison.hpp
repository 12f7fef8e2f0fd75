// Real-vs-replicate comparison of the battery: per-cell z, the family-wise max-|z| threshold, the located cells
// and the global gap score. docs/gap.md §Located, §Gap score.
#pragma once

#include <functional>
#include <vector>

#include <Eigen/Core>

#include "host/gap/statistics.hpp"

namespace driftlab::host::gap {

/// Per-cell z of the real log against the replicates, and the same for each replicate left out in turn.
struct Comparison {
    std::vector<double> z;         ///< real log, per cell
    std::vector<double> sim_mean;  ///< replicate mean per cell
    std::vector<double> sim_sd;    ///< replicate standard deviation per cell
    Eigen::MatrixXd loo_z;         ///< replicate r's z against the other R-1 (rows = replicates)
    double threshold = 0.0;        ///< (1 - alpha) quantile over replicates of max |z| (leave-one-out)
};

/// Compares `real` with the replicate matrix (rows = replicates, needs >= 3 rows). `sd_floor`, when given, is per
/// cell the least standard deviation a z divides by: half the statistic's resolution for a count (one lost frame in
/// so many), where replicates that all agree would otherwise make any difference an enormous z.
Comparison compare(const std::vector<double>& real, const Eigen::MatrixXd& replicates, double alpha,
                   const std::vector<double>* sd_floor = nullptr);

/// Which cells a score or a search looks at.
using CellFilter = std::function<bool(const Cell&)>;

/// Global gap: mean z^2 of the real log over the cells `keep` accepts, divided by the same mean averaged over
/// the left-out replicates (so a log the model explains scores about 1). 1 when no cell is accepted; where the
/// replicates agree exactly on every accepted cell, the log's mean z^2 (1 when it agrees too).
double gap_score(const Comparison& cmp, const std::vector<Cell>& layout, const CellFilter& keep);

/// The level-alpha bound of gap_score(): the (1 - alpha)(R + 1)-th order statistic of the same score computed for
/// each left-out replicate (a Monte Carlo test, as for the cell threshold). A score at or below it is a closed gap.
double gap_score_threshold(const Comparison& cmp, const std::vector<Cell>& layout, const CellFilter& keep,
                           double alpha);

/// A cell that is both significant (|z| above the threshold) and beyond its practical margin.
struct LocatedCell {
    std::size_t index = 0;  ///< into the layout
    double real = 0.0;      ///< the real log's value
    double sim_mean = 0.0;
    double z = 0.0;
    double ratio = 0.0;          ///< real/sim for log-scale statistics; NaN otherwise
    double difference = 0.0;     ///< real - sim in the statistic's own scale (counts, correlation)
    double interval_low = 0.0;   ///< 95 % interval of the difference (ratio, for log-scale statistics): the real
    double interval_high = 0.0;  ///< value against the replicates' spread, difference +- 1.96 sd
};

/// The located cells, largest |z| first.
std::vector<LocatedCell> locate(const std::vector<double>& real, const Comparison& cmp,
                                const std::vector<Cell>& layout);

}  // namespace driftlab::host::gap
