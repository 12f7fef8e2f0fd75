// Is a level step left in the log once the diagnosis has explained it? No effect of the library makes an abrupt,
// lasting change of the mean (a mode hop, a knocked connector), yet a random walk or a long-memory Gauss-Markov
// process closes the battery's gap around one. The test whitens the differenced residual with the model's own
// noise spectrum, where a step becomes a single impulse, and takes the largest standardised impulse
// (the additive-outlier statistic of a stationary Gaussian series, computed in the frequency domain:
// T(theta) = (S^-1 d)_theta / sqrt((S^-1)_theta,theta)); its null distribution comes from replicates of the model.
// docs/gap.md §Level steps.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "host/gap/gap_model.hpp"

namespace driftlab::host::gap {

struct LevelStep {
    bool tested = false;       ///< false: no test was run (the fields below are defaults)
    Channel channel = Channel::gyro;
    double t_s = 0.0;          ///< instant of the largest standardised step [s]
    double size_counts = 0.0;  ///< its estimated size [counts]
    double statistic = 0.0;    ///< largest |T| over the log (2 % kept clear of each end)
    double p_value = 1.0;      ///< Monte Carlo: (1 + replicates at least as large) / (1 + replicates)
    bool significant = false;  ///< p_value <= alpha
};

/// Tests channel `c` of the log (`t_s`, `y`) against `model`, whose Gaussian-process effects on that channel are
/// `spectral_effects` with `spectral_params` (concatenated, candidate_param_names() order; refitted on the whole
/// log together with the white floor before whitening).
LevelStep test_level_step(const GapModel& model, Channel c, const std::vector<double>& t_s, const std::vector<double>& y,
                          const std::vector<std::string>& spectral_effects, const std::vector<double>& spectral_params,
                          int replicates, std::uint64_t seed, int threads, double alpha);

}  // namespace driftlab::host::gap
