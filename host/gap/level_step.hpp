// Is a level step left in the log once the diagnosis has explained it? No effect of the library makes an abrupt,
// lasting change of the mean (a mode hop, a knocked connector), yet a random walk or a long-memory Gauss-Markov
// process closes the battery's gap around one. The test pits the explanation against its non-nested rival, the
// white floor with two level steps (a hop and a return), by their Whittle likelihoods on the whole log: Cox's test
// of separate families, with the null distribution of the likelihood difference from replicates of the explanation
// (a parametric bootstrap). The rival must also win by the Schwarz (BIC) price of its extra parameters, the
// consistent choice for the number of change points: a walk with heavy-tailed increments holds a few large ones,
// which a Gaussian replicate lacks, and is still a walk. docs/gap.md §Level steps.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "host/gap/gap_model.hpp"

namespace driftlab::host::gap {

struct StepEstimate {
    double t_s = 0.0;          ///< instant of the step [s]
    double size_counts = 0.0;  ///< its estimated size [counts]
};

struct LevelStep {
    bool tested = false;       ///< false: no test was run (the fields below are defaults)
    Channel channel = Channel::gyro;
    std::array<StepEstimate, 2> steps{};  ///< the rival's two steps, the larger first (2 % kept clear of each end)
    double statistic = 0.0;    ///< Whittle nll of the explanation minus the rival's: > 0 where the steps fit better
    double margin = 0.0;       ///< the BIC price of the rival's extra parameters, ln(n) / 2 each [nll units]
    double p_value = 1.0;      ///< Monte Carlo: (1 + replicates at least as large) / (1 + replicates)
    bool significant = false;  ///< leaves_step() at the test's alpha
};

/// A level step no library effect makes: the rival beats the explanation beyond the model's own replicates (level
/// alpha) and by more than its extra parameters' price.
bool leaves_step(const LevelStep& s, double alpha);

/// Tests channel `c` of the log (`t_s`, `y`) against `model`, whose Gaussian-process effects on that channel are
/// `spectral_effects` with `spectral_params` (concatenated, candidate_param_names() order; refitted on the whole
/// log together with the white floor before whitening).
LevelStep test_level_step(const GapModel& model, Channel c, const std::vector<double>& t_s, const std::vector<double>& y,
                          const std::vector<std::string>& spectral_effects, const std::vector<double>& spectral_params,
                          int replicates, std::uint64_t seed, int threads, double alpha);

}  // namespace driftlab::host::gap
