// Is a level step left in the log once the diagnosis has explained it? No effect of the library makes an abrupt,
// lasting change of the mean (a mode hop, a knocked connector), yet a random walk or a long-memory Gauss-Markov
// process closes the battery's gap around one. Two Monte Carlo tests against replicates of the explanation,
// combined by their smaller p-value (step_p_values()):
// - the impulse test: the differenced residual, whitened by the explanation's own spectrum, where a step becomes a
//   single impulse; the largest standardised impulse T = max_theta (S^-1 d)_theta / sqrt((S^-1)_theta,theta) (the
//   additive-outlier statistic). Strong against a large step, weak against a small one that the explanation's
//   fitted walk has absorbed;
// - the rival test: the explanation against its non-nested rival, the white floor with two level steps (a hop and a
//   return), by their Whittle likelihoods on the whole log (Cox's test of separate families, its null distribution
//   simulated). The rival must also win by the Schwarz (BIC) price of its extra parameters, the consistent choice
//   for the number of change points: a walk with heavy-tailed increments holds a few large ones, which a Gaussian
//   replicate lacks, and is still a walk.
// A step either test finds makes the log unexplained only where the explanation is a stand-in for it: where its
// processes, refitted beside two steps (and eq. 1), still beat the white floor by their Schwarz price, the steps are
// read as outsized increments of a heavy-tailed process (a Student-t walk) and reported as such.
// docs/gap.md §Level steps.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "host/gap/gap_model.hpp"

namespace driftlab::host::gap {

struct StepEstimate {
    double t_s = 0.0;          ///< instant of the step [s]
    double size_counts = 0.0;  ///< its estimated size [counts]
};

struct LevelStep {
    bool tested = false;  ///< false: no test was run (the fields below are defaults)
    Channel channel = Channel::gyro;
    std::array<StepEstimate, 2> steps{};  ///< the rival's two steps, the larger first (2 % kept clear of each end)
    double impulse = 0.0;                 ///< largest standardised impulse under the explanation's whitening
    double impulse_p = 1.0;               ///< its Monte Carlo p: (1 + replicates at least as large) / (1 + replicates)
    double statistic = 0.0;  ///< Whittle nll of the explanation minus the rival's: > 0 where the steps fit better
    double margin = 0.0;     ///< the BIC price of the rival's extra parameters, ln(n) / 2 each [nll units]
    double rival_p = 1.0;    ///< the statistic's Monte Carlo p
    double p_value = 1.0;    ///< Monte Carlo p of the smaller p (the rival's only where it exceeds the margin)
    /// The explanation's processes refitted beside the rival's steps: Whittle nll of the floor with the steps minus
    /// theirs (> 0 where the processes are there beyond the steps), and the Schwarz price of their parameters.
    double process_gain = 0.0;
    double process_margin = 0.0;
    bool process_beside_steps = false;  ///< process_gain > process_margin: the steps may be the process's increments
    bool significant = false;           ///< leaves_step() at the test's alpha: a step no library effect makes
    bool outsized = false;  ///< p_value <= alpha with the processes beside the steps: read as their outsized increments
};

struct StepPValues {
    double impulse = 1.0;   ///< the impulse's rank p among the log and the replicates
    double rival = 1.0;     ///< the rival statistic's
    double combined = 1.0;  ///< the rank p of the smaller of the two (the rival's counting only above `margin`)
};

/// The level-step test's p-values from the replicates' statistics (`null`, one row per replicate: impulse, rival
/// statistic) and the log's. The smaller p is referred to the same smaller p of every replicate: an exact Monte
/// Carlo test, where twice the smaller (Bonferroni) is conservative, since the two tests respond to the same
/// features and under the explanation the margin rarely lets the rival count.
StepPValues step_p_values(const Eigen::MatrixXd& null, double impulse, double statistic, double margin);

/// A level step no library effect makes: p_value <= alpha, and the explanation's processes are not there beyond the
/// rival's steps (where they are, the steps are read as outsized increments of a heavy-tailed process, reported but
/// no reason to reject it: a mode hop on a white floor leaves nothing for a process once its two steps are out).
bool leaves_step(const LevelStep& s, double alpha);

/// What a level-step test says, in words the report and the terminal share: a step no library effect makes (the log
/// is unexplained), the processes' outsized increments, or none beyond the model's own.
const char* step_reading(const LevelStep& s);

/// Tests channel `c` of the log (`t_s`, `y`) against `model`, whose Gaussian-process effects on that channel are
/// `spectral_effects` with `spectral_params` (concatenated, candidate_param_names() order; kept, only the white floor
/// is estimated on the log), at level `alpha` with at least `replicates` replicates (and at least 4 / alpha).
LevelStep test_level_step(const GapModel& model, Channel c, const std::vector<double>& t_s,
                          const std::vector<double>& y, const std::vector<std::string>& spectral_effects,
                          const std::vector<double>& spectral_params, int replicates, std::uint64_t seed, int threads,
                          double alpha);

/// A mean shape against its rival, two level steps (a hop and a return). A mode hop drawn by a second time constant
/// or a sine closes the battery's gap, as a random walk does around one; but two steps describe it better than the
/// shape, while a thermostat's cycles or an RC network's rise are no steps. Both are fitted to the whole log over the
/// current model (eq. 1 and the shapes accepted before): the shape jointly with eq. 1 (`shape_residual`), the steps
/// by least squares on the current model's residual (`base_residual`; the best two change points whose steps have
/// opposite signs: two the same way are a staircase, as a warm-up's unmodelled curvature draws), jointly with the
/// orthonormal columns `beside` (eq. 1's tangent: eq. 1 refitted beside the steps, linearised, as it is beside the
/// shape; without it eq. 1 stays bent toward a hop and the steps lose what the bend took). Their
/// Gaussian likelihoods of a white floor are compared, each output counting 1 / `long_run_factor` (the smoother's
/// overlapping windows make neighbouring outputs share noise), and the steps must win by the Schwarz price of their
/// parameters beyond the shape's (two instants and two sizes against `shape_parameters`; ln n / 2 each).
struct StepsOverShape {
    bool tested = false;
    std::array<StepEstimate, 2> steps{};  ///< the two steps, in time order
    double statistic = 0.0;               ///< the shape's negative log-likelihood minus the steps' [nll units]
    double margin = 0.0;                  ///< the Schwarz price of the steps' extra parameters
    bool steps_win = false;               ///< statistic > margin: a level step no library effect makes
};
StepsOverShape steps_over_shape(const std::vector<double>& t_s, const std::vector<double>& base_residual,
                                const std::vector<double>& shape_residual, int shape_parameters, double long_run_factor,
                                const Eigen::MatrixXd& beside);

}  // namespace driftlab::host::gap
