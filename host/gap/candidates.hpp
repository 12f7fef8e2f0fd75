// The candidate effects the diagnosis tries, each with <= 3 parameters in physical units (adc_dnl: one transition
// per code the log crosses, on raw-mode logs only), and how a parameter vector becomes an effect of the
// simulator's library (sim/effects) acting on one channel. Effects a static log
// cannot identify, and effects this version does not try, are listed with the reason. docs/gap.md §Candidates.
#pragma once

#include <string>
#include <vector>

#include "driftlab/channels.hpp"
#include "host/gap/gap_model.hpp"

namespace driftlab::host::gap {

/// How a candidate's parameters are found.
enum class FitRoute {
    deterministic,  ///< a mean shape: variable projection on the fitting part of the log, jointly with eq. 1
    spectral,       ///< a Gaussian process: debiased Whittle likelihood of the differenced residual (spectral_fit)
    simulated,  ///< a non-Gaussian process: Nelder-Mead on log-parameters against the battery (common random numbers)
    code_density,  ///< the converter's transitions: a probit fit per code to a raw-mode log's raw codes (code_density)
};

struct CandidateInfo {
    std::string effect;                   ///< library name (sim/effects)
    std::vector<std::string> param_keys;  ///< unit-suffixed; "_unit" is the channel's unit (dps or g); empty: per fit
    FitRoute route;
    std::string settle;  ///< the experiment that separates it from its look-alikes
};

/// The candidates, in the order they are tried.
const std::vector<CandidateInfo>& candidate_list();

/// The candidate called `effect`; throws std::invalid_argument when there is none.
const CandidateInfo& candidate(const std::string& effect);

/// The candidate called `effect`, or null.
const CandidateInfo* find_candidate(const std::string& effect);

/// Effects of the library a static bench log cannot identify, with the reason.
struct NotIdentifiable {
    std::string effect;
    std::string reason;
};
const std::vector<NotIdentifiable>& not_identifiable_list();

/// The candidates a log without raw codes cannot have tried (those fitted to raw codes), with the reason.
std::vector<NotIdentifiable> not_tried_without_raw_codes(bool codes_carry_motion = false);

/// The library effect for candidate `effect` on channel `c` with parameters `params` (candidate_list() keys,
/// physical units). Throws std::invalid_argument for an unknown name.
sim::EffectSpec make_candidate_effect(const std::string& effect, Channel c, const std::vector<double>& params,
                                      const GapModel& model);

/// The model's noise-free mean of channel `c` at the instants `t_s` [counts, up to a constant]: eq. 1 plus the
/// deterministic candidates among `model.effects`, evaluated by the library's own effects.
std::vector<double> model_mean_counts(const GapModel& model, Channel c, const std::vector<double>& t_s);

/// The size on channel `c` of a model file's effect `spec` that a mean-shape or Gaussian-process candidate of the
/// same name would fit (C3, the cycle's coupling times its swing, sigma, B or K) [physical units]; 0 where it has
/// none, and for every other effect.
double candidate_size_in(const sim::EffectSpec& spec, Channel c);

/// `spec` (a mean shape or Gaussian process) with its size on channel `c` set to zero and every other key as the
/// library reads it: what the file gives the other channels. Throws std::invalid_argument for other effects.
sim::EffectSpec without_channel(const sim::EffectSpec& spec, Channel c);

/// A model file's Gaussian process (gauss_markov, flicker, rate_random_walk) on channel `c` as the candidate of the
/// same name states it (candidate_param_names() order, physical units); flicker's band is not among them. Throws
/// std::invalid_argument for other effects.
std::vector<double> file_process_params(const sim::EffectSpec& spec, Channel c);

/// Adds the spectrum of the model file's Gaussian process `spec` on channel `c` (flicker with the file's own band)
/// to `held`.
void hold_noise(HeldNoise& held, const sim::EffectSpec& spec, Channel c, const GapModel& model);

/// Parameter keys with the channel's unit spelled out (e.g. "c3_dps" for the gyro, "c3_g" for an accel axis).
std::vector<std::string> candidate_param_names(const std::string& effect, Channel c);

}  // namespace driftlab::host::gap
