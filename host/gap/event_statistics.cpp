// Event summaries of the gap battery; see event_statistics.hpp.
#include "host/gap/event_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace driftlab::host::gap {

double log_kurtosis(const std::vector<double>& y) {
    double mean = 0.0;
    for (double v : y) mean += v;
    mean /= static_cast<double>(y.size());
    double m2 = 0.0, m4 = 0.0;
    for (double v : y) {
        const double d2 = (v - mean) * (v - mean);
        m2 += d2;
        m4 += d2 * d2;
    }
    const double n = static_cast<double>(y.size());
    m2 /= n;
    m4 /= n;
    // A constant series has no tails: report the Gaussian value rather than 0/0.
    return m2 > 0.0 ? std::log(m4 / (m2 * m2)) : std::log(3.0);
}

double log_jump_ratio(const std::vector<double>& y, std::size_t blocks) {
    if (blocks < 3 || y.size() < blocks) throw std::invalid_argument("log_jump_ratio: need >= 3 blocks of >= 1 sample");
    std::vector<double> means(blocks, 0.0);
    for (std::size_t b = 0; b < blocks; ++b) {
        const std::size_t lo = y.size() * b / blocks, hi = y.size() * (b + 1) / blocks;
        for (std::size_t i = lo; i < hi; ++i) means[b] += y[i];
        means[b] /= static_cast<double>(hi - lo);
    }
    // Largest over root-mean-square step: bounded by sqrt(blocks - 1), so its spread under the null is narrow and
    // it cannot inflate the battery's max-|z| threshold the way a ratio to the median would.
    double largest = 0.0, sum2 = 0.0;
    for (std::size_t b = 0; b + 1 < blocks; ++b) {
        const double step = means[b + 1] - means[b];
        largest = std::max(largest, std::abs(step));
        sum2 += step * step;
    }
    if (sum2 <= 0.0) return 0.0;  // a constant series has no step
    return std::log(largest / std::sqrt(sum2 / static_cast<double>(blocks - 1)));
}

}  // namespace driftlab::host::gap
