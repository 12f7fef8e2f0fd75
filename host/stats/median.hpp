// The median every analysis takes: the middle order statistic, no interpolation.
#pragma once

#include <vector>

namespace driftlab::host::stats {

/// The element at index n/2 of `values` sorted (for an even count the upper of the two middle values); NaN when
/// `values` is empty. Takes its own copy, which it reorders (linear time, std::nth_element).
double median(std::vector<double> values);

}  // namespace driftlab::host::stats
