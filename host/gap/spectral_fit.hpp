// Maximum (debiased) Whittle likelihood of the Gaussian noise candidates (gauss_markov, flicker,
// rate_random_walk), one or several together, jointly with the white floor, on the differenced residual of one
// part of the log. The parameters are the library effect's own (physical units); the spectrum at the output
// instants is built from the same quantities the effect simulates (flicker: the library's own Gauss-Markov
// components). docs/gap.md §Spectral likelihood.
#pragma once

#include <string>
#include <vector>

#include "host/gap/gap_model.hpp"
#include "host/gap/whittle.hpp"

namespace driftlab::host::gap {

/// The output noise of a white floor of variance `white` [counts^2 per conversion] plus the spectral candidates
/// `effects` on channel `c`, whose parameters (candidate_param_names() order, physical units) are concatenated in
/// `params`, plus the model file's processes the model holds on the channel (`model.held`).
OutputSpectrum model_spectrum(const std::vector<std::string>& effects, Channel c, const std::vector<double>& params,
                              const GapModel& model, double white);

struct SpectralFit {
    std::vector<std::string> effects;
    std::vector<double> params;  ///< the effects' parameters, concatenated (physical units)
    double white = 0.0;          ///< white floor [counts^2 per conversion]
    double nll = 0.0;            ///< Whittle negative log-likelihood at the optimum
    int free_parameters = 1;     ///< the white floor plus the effects' parameters
};

/// Whittle ML of the white floor plus `effects` (none: the floor alone, in closed form unless the model holds a
/// process on the channel) beside the held processes, on periodogram `p` of
/// channel `c`. `known` (optional) starts all effects but the last from these parameters (a stepwise refit);
/// the last starts from a grid over its plausible range.
SpectralFit fit_spectral(const std::vector<std::string>& effects, Channel c, const GapModel& model,
                         const PartPeriodogram& p, const std::vector<double>& known = {});

/// Whittle negative log-likelihood of a fitted model on a periodogram (per-frequency terms in `terms`).
double spectral_nll(const SpectralFit& fit, Channel c, const GapModel& model, const PartPeriodogram& p,
                    std::vector<double>* terms = nullptr);

/// How an information criterion charges one parameter, in units of 2 x nll: AIC 2, BIC ln(observations).
enum class InformationCriterion { aic, bic };
const char* criterion_name(InformationCriterion ic);
double parameter_price(InformationCriterion ic, double observations);

}  // namespace driftlab::host::gap
