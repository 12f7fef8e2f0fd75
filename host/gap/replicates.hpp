// The simulate-refit parametric bootstrap: R replicates of the calibrated model on the real log's instants, each
// refitted and summarised by the same battery as the real log. Replicate r uses the seed replicate_seed(seed, r)
// whatever the model, so two models compared with the same seed share their random numbers (common random
// numbers: smooth objectives for the candidate fits). docs/gap.md §In one paragraph.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "host/fit/lm_fit.hpp"
#include "host/gap/gap_model.hpp"
#include "host/gap/statistics.hpp"

namespace driftlab::host::gap {

/// Seed of replicate `r` of a run seeded with `seed`.
std::uint64_t replicate_seed(std::uint64_t seed, int r);

/// Fills a replicate's request with signals beyond the model (gap-eval's oracle: a fresh realisation of the
/// truth generator per replicate, seeded from the replicate's seed).
using ReplicateExtra = std::function<void(std::uint64_t replicate_seed, sim::OutputRequest& request)>;

/// What one replicate is reduced to (one row of the result): its smoothed outputs and, when asked for, the raw
/// codes of the same rows (else empty).
using ReplicateSummary =
    std::function<std::vector<double>(const sim::Outputs& simulated, const sim::Outputs& raw_codes)>;

/// `summary` of `replicates` replicates (rows) of `model` on the instants `t_s` for `channels`, run on `threads`
/// threads, with raw codes when `raw_codes`. Every row must have the same length.
Eigen::MatrixXd simulate_replicates(const GapModel& model, const std::vector<double>& t_s,
                                    const std::array<bool, kChannelCount>& channels, int replicates, std::uint64_t seed,
                                    int threads, const ReplicateSummary& summary, const ReplicateExtra& extra = {},
                                    bool raw_codes = false);

/// The eq. 1 fit options of a replicate of `model`'s channel `c`: started at the model's drift.
fit::FitOptions start_at_model(const GapModel& model, Channel c);

/// Battery values of `replicates` replicates (rows) on the instants `t_s`, run on `threads` threads.
Eigen::MatrixXd run_replicates(const GapModel& model, const std::vector<double>& t_s, const BatteryOptions& options,
                               int replicates, std::uint64_t seed, int threads, const ReplicateExtra& extra = {});

}  // namespace driftlab::host::gap
