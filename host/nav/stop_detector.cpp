#include "host/nav/stop_detector.hpp"

#include <cmath>

#include "host/stats/chi_square.hpp"

namespace driftlab::host::nav {

StopDetector::StopDetector(double window_s, const std::array<double, 3>& reading_sd)
    : window_s_(window_s), sd_(reading_sd) {}

void StopDetector::push(double t_s, const ImuReading& r) {
    const Entry e{t_s, {r.yaw_rate, r.ax, r.ay}};
    window_.push_back(e);
    for (std::size_t k = 0; k < 3; ++k) sum_[k] += e.v[k], sum2_[k] += e.v[k] * e.v[k];
    while (window_.size() > 1 && window_.back().t_s - window_.front().t_s > window_s_) {
        for (std::size_t k = 0; k < 3; ++k)
            sum_[k] -= window_.front().v[k], sum2_[k] -= window_.front().v[k] * window_.front().v[k];
        window_.pop_front();
    }
}

bool StopDetector::quiet(const std::array<double, 3>& bias, const std::array<double, 3>& bias_sd) const {
    const std::size_t n = window_.size();
    // Full: the window spans its length to within one row.
    if (n < 3 || window_.back().t_s - window_.front().t_s < window_s_ * (1.0 - 1.0 / static_cast<double>(n)))
        return false;
    if (variance_bound_.size() <= n) variance_bound_.resize(n + 1, 0.0);
    double& bound = variance_bound_[n];
    const double dof = static_cast<double>(n - 1);
    if (bound == 0.0) bound = stats::chi_square_quantile(0.99, dof) / dof;
    for (std::size_t k = 0; k < 3; ++k) {
        const double mean = sum_[k] / static_cast<double>(n);
        const double var = std::max(0.0, (sum2_[k] - static_cast<double>(n) * mean * mean) / dof);
        if (var > sd_[k] * sd_[k] * bound) return false;
        const double mean_sd = std::sqrt(sd_[k] * sd_[k] / static_cast<double>(n) + bias_sd[k] * bias_sd[k]);
        if (std::abs(mean - bias[k]) > 3.0 * mean_sd) return false;
    }
    return true;
}

}  // namespace driftlab::host::nav
