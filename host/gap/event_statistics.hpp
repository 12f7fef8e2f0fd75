// The battery's summaries of isolated events, which second-order statistics (ADEV, PSD, ACF) smear out:
// heavy tails (spikes, bursts) and abrupt level changes (a step between two blocks of the residual).
// docs/gap.md §Statistics.
#pragma once

#include <cstddef>
#include <vector>

namespace driftlab::host::gap {

/// ln of the kurtosis m4 / m2^2 of `y` (mean removed); 3 for Gaussian samples, larger with spikes.
double log_kurtosis(const std::vector<double>& y);

/// ln of the largest step between the means of `blocks` consecutive equal blocks of `y`, over the root mean
/// square step: between 0 and ln sqrt(blocks - 1). Independent of scale and of any Gaussian wander (whose steps
/// are alike); near its bound when one step stands out (a level jump). Needs blocks >= 3 and y.size() >= blocks.
double log_jump_ratio(const std::vector<double>& y, std::size_t blocks);

}  // namespace driftlab::host::gap
