// The median; see median.hpp.
#include "host/stats/median.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace driftlab::host::stats {

double median(std::vector<double> values) {
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

}  // namespace driftlab::host::stats
