// Which effect closes the gap: each candidate is fitted jointly with the base on the FITTING part of the log,
// then judged on the HELD-OUT part. Accepted only if the synthetic likelihood of the fitting cells improves by
// more than a BIC-like penalty per parameter AND the held-out gap shrinks by a clear margin. Among accepted
// candidates whose signal is Gaussian (mean shapes and Gaussian processes), the full-log spectral BIC chooses;
// spikes (non-Gaussian) compete with that choice on the held-out synthetic likelihood. Effects are added
// stepwise (up to max_effects); where a Gaussian process is chosen over an accepted mean shape, the path that takes
// the shape first is searched too (a process can swallow a shape with the rest). docs/gap.md §Candidates.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "host/gap/gap_model.hpp"
#include "host/gap/level_step.hpp"
#include "host/gap/spectral_fit.hpp"
#include "host/gap/statistics.hpp"

namespace driftlab::host::gap {

struct GivenEffects;

struct ExplainOptions {
    int fit_replicates = 8;           ///< replicates per objective evaluation of a simulated-route fit (spikes)
    int eval_replicates = 40;         ///< replicates when judging a fitted candidate
    int max_evaluations = 18;         ///< Nelder-Mead budget per simulated-route candidate (the budget gap-eval scores)
    int max_effects = 3;              ///< stepwise limit over the whole log
    double penalty_per_param = 0.25;  ///< x ln(cells): the BIC-like price of one parameter (tuned by gap-eval)
    double min_heldout_shrink = 0.4;  ///< the held-out gap excess must shrink by at least this fraction (tuned)
    double ambiguity_z = 1.96;        ///< runner-up not separated from the best at this z (close_call): ambiguous
    double step_alpha = 0.05;         ///< level of the level-step test (tuned by gap-eval)
    /// Family-wise level of the cells a candidate leaves located, and of the held-out bound a step is marked
    /// against (Explanation::heldout_bound); diagnose() sets it from GapOptions::alpha.
    double alpha = 0.05;
    /// Choice among Gaussian candidates (tuned)
    InformationCriterion information_criterion = InformationCriterion::aic;
    /// Where a Gaussian process is chosen over an accepted mean shape, the path that takes the shape instead is
    /// searched too, and kept when its final model's spectral criterion is lower by more than this (2 x nll units).
    /// On single-process logs of tuning seeds it won by more in 2 of 240 (docs/gap.md §Choice).
    double shape_path_margin = 5.0;
    int step_replicates = 40;  ///< at least this many replicates for the level-step test's null
    /// Level-step test every accepted Gaussian-process candidate (gap-eval, whose tuned thresholds may choose any of
    /// them). driftlab gap tests its final model instead (diagnose()), which the choice does not depend on.
    bool step_test_candidates = false;
    /// > 0: a channel without located cells is still searched when its held-out gap score exceeds its Monte Carlo
    /// bound at this level (a diffuse gap: many cells a little off, none alone beyond the family-wise threshold).
    /// 0 (the default, and what gap-eval scores): only channels with located cells are searched.
    double diffuse_alpha = 0.0;
    std::vector<std::string> candidates;  ///< empty = all of candidate_list()
    /// The base's own effects (add_given_effects()). Where the base holds a process, the candidate of the same name
    /// is fitted in place of it (its values may be what the log disagrees with), never beside it (both would draw
    /// the same random numbers); a refitted shape's name is not tried again on its channel.
    const GivenEffects* given = nullptr;
    std::function<void(const std::string& stage)> progress;  ///< optional: told what is being fitted
    std::uint64_t seed = 1;
    int threads = 2;
};

/// One fitted candidate on one channel.
struct Explanation {
    std::string effect;
    std::string channel;
    std::vector<std::pair<std::string, double>> params;  ///< physical units, keys as in the effect library
    double gap_before = 1.0;                             ///< this channel's gap score on the fitting part, base only
    double gap_after = 1.0;                              ///< ... with the candidate
    double heldout_before = 1.0;                         ///< on the held-out part, base only
    double heldout_after = 1.0;                          ///< ... with the candidate
    double heldout_shrink = 0.0;  ///< 1 - (after - 1) / (before - 1): fraction of the held-out excess removed
    /// The level-alpha (ExplainOptions::alpha) Monte Carlo bound of the channel's held-out score under the model
    /// before this step: a score within it is one the model leaves by chance (the bound the verdict's "the gap
    /// closes" reads, per channel).
    double heldout_bound = 0.0;
    double loss_gain = 0.0;  ///< synthetic log-likelihood gain on all cells (x2), parameters from the fitting part
    double penalty = 0.0;    ///< parameters x ln(cells): the BIC price before penalty_per_param
    double heldout_loss_gain = 0.0;         ///< synthetic log-likelihood gain on the held-out cells (x2)
    std::vector<double> heldout_cell_loss;  ///< per held-out cell: z^2 + 2 ln sd with the candidate (close_call)
    bool gaussian = false;                  ///< a mean shape or a Gaussian process: compared by the spectral likelihood
    double spectral_gain = 0.0;             ///< 2 x (full-log Whittle nll of the current model - with the candidate)
    int spectral_extra_parameters = 0;      ///< parameters the candidate adds to that fit (its own, or its shape's)
    double spectral_observations = 0.0;     ///< differences in the full-log spectral likelihood
    std::vector<double> spectral_terms;     ///< per Fourier frequency: Whittle nll with the candidate (close_call)
    bool long_memory = false;               ///< a Gauss-Markov fit whose correlation time exceeds 1/20 of the log
    std::size_t cells_left = 0;             ///< this channel's cells still located with the candidate in the model
    LevelStep residual_step;     ///< level-step test with the candidate (Gaussian processes; step_test_candidates)
    StepsOverShape shape_steps;  ///< a mean shape against two level steps (accepted shapes on a white floor)
    bool accepted = false;
    int step = 0;                 ///< stepwise round in which it was tried (1-based)
    bool replaces_given = false;  ///< fitted in place of the model file's process of the same name on the channel
    /// An added mean shape or Gaussian process: its parameters estimated again on the whole log once chosen
    /// (ExplainResult::whole_log_model); empty otherwise. `params` are the fitting part's, which the held-out part
    /// judged.
    std::vector<std::pair<std::string, double>> whole_log_params;
    std::string ambiguous_with;  ///< a candidate nearly as good, or ""
    std::string settle;          ///< the experiment that would separate them

    /// Tried while the channel's held-out score lay within its bound: a step can still add an effect then (a cell of
    /// either part located, or after the first step an excess over 0.2 left), on weaker evidence than a gap the model
    /// cannot leave.
    bool within_bound_before() const { return heldout_before <= heldout_bound; }

    /// The parameters the diagnosis reports: the whole log's where there are, else the fitting part's.
    const std::vector<std::pair<std::string, double>>& estimate() const {
        return whole_log_params.empty() ? params : whole_log_params;
    }
};

/// The effects of the model the log is diagnosed on (`gap --model FILE`), in the base before anything is located:
/// see add_given_effects().
struct GivenEffects {
    std::vector<Explanation> refitted;   ///< mean shapes fitted to this log, one channel each (effect, channel, params)
    std::vector<Explanation> held;       ///< Gaussian processes at the file's values, one channel each
    std::vector<std::size_t> held_slot;  ///< per `held` entry: its spec in GapModel::effects
    std::vector<std::string> kept;       ///< kept as the file gives them: effects the diagnosis does not fit, and
                                         ///< shapes or processes the file gives channels not analysed

    bool empty() const { return refitted.empty() && held.empty() && kept.empty(); }
};

/// A step where a Gaussian process was chosen over an accepted mean shape, and both paths were searched on.
struct PathChoice {
    int step = 0;
    std::string channel;
    std::string process, shape;      ///< the first effect of each path
    double criterion_process = 0.0;  ///< the channel's full-log spectral criterion at the path's end
    double criterion_shape = 0.0;
    bool shape_kept = false;  ///< criterion_shape + shape_path_margin < criterion_process
};

struct ExplainResult {
    GapModel model;                     ///< base plus the accepted effects
    GapModel whole_log_model;           ///< the same with their parameters estimated again on the whole log
    std::vector<Explanation> tried;     ///< every fit on the kept path, accepted first, then by held-out gap
    std::vector<Explanation> accepted;  ///< in the order they were added
    std::vector<PathChoice> paths;      ///< the kept path's branch points, in step order
};

/// The acceptance rule: likelihood gain on all cells above penalty_per_param x penalty, a held-out gap to shrink,
/// a held-out shrink of at least min_heldout_shrink and a held-out likelihood gain.
bool passes(const Explanation& e, double penalty_per_param, double min_heldout_shrink);

/// The full-log spectral information criterion of the current model minus that with the candidate (> 0 favours
/// the candidate).
double delta_ic(const Explanation& e, InformationCriterion ic);

/// Whether delta_ic() means anything: the spectral evidence is computed for accepted Gaussian candidates only.
inline bool has_delta_ic(const Explanation& e) { return e.gaussian && e.accepted; }

/// Whether `runner_up` is not separated from `best`: always when one is a long-memory Gauss-Markov fit and the
/// other flicker or a random walk (look-alikes within the log); otherwise Vuong's test for non-nested models
/// (Vuong, Econometrica 57(2), 1989) with d_j the runner-up's minus the best's loss: over the Fourier frequencies of
/// the full-log spectral likelihood when both are Gaussian (corrected for their parameter counts by `ic`), over
/// the held-out cells otherwise; close when sum d_j < z sqrt(n) sd(d).
bool close_call(const Explanation& best, const Explanation& runner_up, double z, InformationCriterion ic);

/// The verdict among one channel's passing candidates: the Gaussian one with the largest delta_ic, unless spikes
/// beat it on the held-out synthetic likelihood; the runner-up is the next Gaussian candidate, else spikes. A
/// long-memory Gauss-Markov fit gives way to an accepted random walk or flicker (within the log it is one of them,
/// with a parameter more), and becomes the runner-up, unless it beats the better of them by more than that
/// parameter's price: a walk fitted as one gains about the price, a process whose fit ran past L/20 can gain more.
struct Choice {
    const Explanation* best = nullptr;
    const Explanation* runner_up = nullptr;
};
Choice choose(const std::vector<const Explanation*>& passing, InformationCriterion ic);

/// Whether the explanation leaves no level step: a random process explains a step only by an improbably large
/// increment, and no library effect makes one, so a step left behind makes the verdict "unexplained" unless the
/// process remains beside it (leaves_step(): then the step is read as the process's outsized increment). (Cells may
/// stay located: the library's forms are not the truth's, e.g. bursts of spikes are not single-conversion spikes;
/// cells_left and the gap after report how much remains.)
bool closes_gap(const Explanation& e, double step_alpha);

/// Puts the model file's `effects` into the calibrated `base`. A model states the unit's noise, which the log is to
/// test, while a mean shape's timing and size belong to the power-on and the room, as eq. 1's do: so on each
/// analysed channel where the file gives it a size, a Gaussian process of the candidates is held at the file's
/// values (simulated as the file gives it, and part of every spectrum fitted on the channel: `base.held`), and a mean
/// shape is fitted to the whole log with eq. 1 in the candidate's form (what the file gives other channels is kept).
/// Every other effect is kept as the file gives it. The white noise is then matched again to the log's short-lag
/// spread `target_spread`. base.effects ends with the refitted shapes, in the order returned.
GivenEffects add_given_effects(GapModel& base, const std::vector<sim::EffectSpec>& effects,
                               const std::vector<double>& t_s,
                               const std::array<const std::vector<double>*, kChannelCount>& y,
                               const std::array<bool, kChannelCount>& channels,
                               const std::array<double, kChannelCount>& target_spread, std::uint64_t seed);

/// Explains the gap of the channels in `channels` (those with located cells) on `log_t_s`/`log_y`.
ExplainResult explain(const GapModel& base, const std::vector<double>& t_s,
                      const std::array<const std::vector<double>*, kChannelCount>& y,
                      const std::array<bool, kChannelCount>& channels, const BatteryOptions& battery,
                      const ExplainOptions& options, const RawCodes& raw = {});

}  // namespace driftlab::host::gap
