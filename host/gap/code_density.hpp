// The battery's code histogram of a raw-mode log: the converter's raw codes against what an ideal quantiser makes
// of the level the smoothed output gives, so that a code wider or narrower than its neighbours (DNL, a missing code)
// stands out from the noise and the drift. docs/gap.md §Statistics.
#pragma once

#include <vector>

namespace driftlab::host::gap {

/// ln(1 + G2 / df): the multinomial deviance G2 of the histogram of the integer codes `raw` against an ideal
/// quantiser (code c for inputs in [c - 1/2, c + 1/2)) fed Gaussian noise of deviation s around `level` (the
/// smoothed output of the same rows, [counts]), s fitted to minimise G2; df = codes in the range - 2. Near 0 for
/// an ideal converter; larger when some codes are wider than others. Needs raw.size() == level.size() >= 2.
double code_density_excess(const std::vector<double>& raw, const std::vector<double>& level);

}  // namespace driftlab::host::gap
