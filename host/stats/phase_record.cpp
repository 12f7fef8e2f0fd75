// PhaseRecord: rate or phase samples -> phase plus gap-free segments (docs/allan.md §2).
#include "host/stats/phase_record.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace driftlab::host::stats {
namespace {

void check_arguments(std::size_t n, double tau0_s, std::span<const std::uint8_t> mask) {
    if (!(tau0_s > 0.0) || !std::isfinite(tau0_s)) throw std::invalid_argument("tau0 must be a positive number");
    if (!mask.empty() && mask.size() != n) throw std::invalid_argument("mask length differs from data length");
}

bool is_gap(std::span<const double> v, std::span<const std::uint8_t> mask, std::size_t k) {
    return !std::isfinite(v[k]) || (!mask.empty() && mask[k] != 0);
}

}  // namespace

PhaseRecord PhaseRecord::from_rate(std::span<const double> rate, double tau0_s, std::span<const std::uint8_t> mask) {
    check_arguments(rate.size(), tau0_s, mask);
    PhaseRecord r;
    r.tau0_s_ = tau0_s;
    r.kind_ = InputKind::rate;

    long double sum = 0.0L;
    std::size_t valid = 0;
    for (std::size_t k = 0; k < rate.size(); ++k) {
        if (is_gap(rate, mask, k)) continue;
        sum += rate[k];
        ++valid;
    }
    const long double mean = valid ? sum / static_cast<long double>(valid) : 0.0L;
    r.gap_samples_ = rate.size() - valid;

    // A gap sample adds nothing (it stands at the mean); no term that uses it is ever evaluated.
    std::vector<long double> x(rate.size() + 1, 0.0L);
    std::vector<std::uint8_t> usable(rate.size() + 1, 1);
    std::vector<std::uint8_t> linked(rate.size(), 1);
    for (std::size_t k = 0; k < rate.size(); ++k) {
        x[k + 1] = x[k];
        if (is_gap(rate, mask, k)) {
            linked[k] = 0;
        } else {
            x[k + 1] += (static_cast<long double>(rate[k]) - mean) * tau0_s;
        }
    }
    r.store_scaled(x);
    r.build_segments(usable, linked);
    return r;
}

PhaseRecord PhaseRecord::from_phase(std::span<const double> phase, double tau0_s, std::span<const std::uint8_t> mask) {
    check_arguments(phase.size(), tau0_s, mask);
    PhaseRecord r;
    r.tau0_s_ = tau0_s;
    r.kind_ = InputKind::phase;

    std::vector<std::uint8_t> usable(phase.size(), 1);
    std::vector<std::uint8_t> linked(phase.empty() ? 0 : phase.size() - 1, 1);
    long double origin = 0.0L;
    for (std::size_t k = 0; k < phase.size(); ++k) {
        if (!is_gap(phase, mask, k)) {
            origin = phase[k];
            break;
        }
    }
    // Referencing to the first valid sample keeps magnitudes small; gap samples hold the previous value so
    // that sliding sums stay finite (their terms are skipped).
    std::vector<long double> x(phase.size(), 0.0L);
    long double held = 0.0L;
    for (std::size_t k = 0; k < phase.size(); ++k) {
        if (is_gap(phase, mask, k)) {
            usable[k] = 0;
            ++r.gap_samples_;
        } else {
            held = static_cast<long double>(phase[k]) - origin;
        }
        x[k] = held;
    }
    r.store_scaled(x);
    r.build_segments(usable, linked);
    return r;
}

void PhaseRecord::store_scaled(const std::vector<long double>& x) {
    long double largest = 0.0L;
    for (long double v : x) largest = std::max(largest, std::fabs(v));
    scale_exponent_ = 0;
    if (largest > 0.0L) std::frexp(largest, &scale_exponent_);
    phase_.resize(x.size());
    for (std::size_t k = 0; k < x.size(); ++k) phase_[k] = static_cast<double>(std::ldexp(x[k], -scale_exponent_));
}

void PhaseRecord::build_segments(const std::vector<std::uint8_t>& usable, const std::vector<std::uint8_t>& linked) {
    segments_.clear();
    const std::size_t n = usable.size();
    std::size_t k = 0;
    while (k < n) {
        if (!usable[k]) {
            ++k;
            continue;
        }
        std::size_t end = k + 1;
        while (end < n && usable[end] && linked[end - 1]) ++end;
        if (end - k >= 2) segments_.push_back({k, end});
        k = end;
    }
    if (segments_.empty()) segments_.push_back({0, 0});
}

Segment PhaseRecord::longest_segment() const {
    Segment best = segments_.front();
    for (const Segment& s : segments_) {
        if (s.size() > best.size()) best = s;
    }
    return best;
}

}  // namespace driftlab::host::stats
