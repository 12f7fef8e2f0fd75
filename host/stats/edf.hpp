// Equivalent degrees of freedom of Allan-family variance estimates and the chi-square confidence interval they
// give (docs/allan.md §4). EDF after C. A. Greenhall and W. J. Riley, "Uncertainty of stability variances based
// on finite differences", PTTI 2003 (eqs. 7-13, Tables 1-3); simple fallback after NIST SP 1065 Table 5.
#pragma once

#include <optional>

#include "host/stats/deviation.hpp"

namespace driftlab::host::stats {

/// 1-sigma two-sided confidence (erf(1/sqrt 2)), the level Stable32 prints as "Confidence Factor = 0.683".
inline constexpr double kOneSigmaConfidence = 0.68268949213708585;

/// Greenhall-Riley EDF for a variance of difference order d (2 Allan, 3 Hadamard) at averaging factor m from
/// N phase samples, for power-law noise alpha (S_y ~ f^alpha, integer in [-4, 2], alpha + 2d > 1).
/// `overlapping`: stride 1 estimator; `modified`: the modified (MVAR) filter. Returns nothing for the one case the
/// paper leaves open (white PM, unmodified, fewer than d+1 independent terms) or invalid arguments.
std::optional<double> edf_greenhall(int alpha, int d, double m, double phase_samples, bool overlapping, bool modified);

/// Approximate EDF for overlapping Allan variance, NIST SP 1065 Table 5 (alpha in [-2, 2]); N - 1 otherwise.
double edf_simple(double phase_samples, double m, int alpha);

/// EDF for `type` with the noise alpha clamped to the statistic's valid range; falls back to edf_simple when the
/// Greenhall computation has no answer.
double edf_for(Deviation type, int alpha, double m, double phase_samples);

/// Confidence interval of a deviation from its EDF: sigma^2 edf / chi2_{(1+c)/2} .. sigma^2 edf / chi2_{(1-c)/2}
/// (SP 1065 eq. 45), returned as deviations.
struct ConfidenceInterval {
    double low = 0.0;
    double high = 0.0;
};
ConfidenceInterval confidence_interval(double dev, double edf, double confidence = kOneSigmaConfidence);

}  // namespace driftlab::host::stats
