// The converter's codes in a raw-mode log: the battery's code histogram, which sets the converter's code widths
// against what an ideal quantiser makes of the level the smoothed output gives (DNL, a missing code, stand out from
// the noise and the drift), and the adc_dnl candidate's estimate of the transitions the log crosses.
// docs/gap.md §Statistics and §Candidates.
#pragma once

#include <cstddef>
#include <vector>

namespace driftlab::host::gap {

/// The ideal-quantiser model of a log's raw codes: integer codes `raw`, code c for inputs in [c - 1/2, c + 1/2),
/// the input Gaussian with deviation `s` around `level` (the smoothed output of the same rows, [counts]).
struct CodeDensity {
    double s = 0.0;   ///< the noise deviation that best explains the codes (minimum deviance) [counts]
    double g2 = 0.0;  ///< multinomial deviance of the codes' histogram at that s
    int codes = 0;    ///< codes from the lowest to the highest seen
};

/// Fits s; needs raw.size() == level.size() and two rows with a code (std::invalid_argument otherwise). Rows with a
/// negative code (a lost RAW frame, marked -1) are left out, here and in fit_transitions(). With fewer than three codes
/// there is nothing to compare widths with: s is the rows' own spread and g2 is 0.
CodeDensity code_density(const std::vector<double>& raw, const std::vector<double>& level);

/// The battery's cell: ln(1 + G2 / df), df = codes - 2; about ln 2 for an ideal converter, larger when some codes
/// are wider than others; 0 with fewer than three codes.
double code_density_excess(const std::vector<double>& raw, const std::vector<double>& level);

/// The level a log whose outputs are themselves codes (one conversion each) is compared with, per row: the mean of
/// the `half_width` rows either side, the row itself left out (its own code would make every code fit its level).
/// The same for the log and its replicates, so what averaging leaves of the DNL cancels in the comparison.
std::vector<double> neighbour_level(const std::vector<double>& codes, std::size_t half_width = 16);

/// A converter transition: code `code` begins at input `counts`.
struct FittedTransition {
    long code = 0;
    double counts = 0.0;
};

/// The transitions a raw-mode log crosses and the noise deviation, by maximum likelihood: for each code j above
/// the lowest seen, P(code_t >= j) = Phi((level_t - T_j) / s), a probit in T_j searched within 1 LSB of the ideal
/// j - 1/2, with s shared by all of them (profiled). Only transitions with at least `min_each_side` rows on each
/// side near them are fitted, and those whose estimate reaches the end of the search range (the rows do not place
/// them) are left out; the result is increasing (a transition at or below the previous one is put just above it).
struct TransitionFit {
    double s = 0.0;                             ///< [counts]
    std::vector<FittedTransition> transitions;  ///< by code
};
TransitionFit fit_transitions(const std::vector<double>& raw, const std::vector<double>& level, int min_each_side = 20);

}  // namespace driftlab::host::gap
