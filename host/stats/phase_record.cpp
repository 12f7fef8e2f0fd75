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

template <class Visit>
void PhaseRecord::store_scaled(std::size_t n, const Visit& visit) {
    long double largest = 0.0L;
    visit([&](std::size_t, long double v) { largest = std::max(largest, std::fabs(v)); });
    scale_exponent_ = 0;
    if (largest > 0.0L) std::frexp(largest, &scale_exponent_);
    phase_.resize(n);
    visit([&](std::size_t k, long double v) { phase_[k] = static_cast<double>(std::ldexp(v, -scale_exponent_)); });
}

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
    std::vector<std::uint8_t> usable(rate.size() + 1, 1);
    std::vector<std::uint8_t> linked(rate.size(), 1);
    for (std::size_t k = 0; k < rate.size(); ++k) linked[k] = is_gap(rate, mask, k) ? 0 : 1;
    r.store_scaled(rate.size() + 1, [&](const auto& each) {
        long double x = 0.0L;
        each(0, x);
        for (std::size_t k = 0; k < rate.size(); ++k) {
            if (linked[k]) x += (static_cast<long double>(rate[k]) - mean) * tau0_s;
            each(k + 1, x);
        }
    });
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
    for (std::size_t k = 0; k < phase.size(); ++k) {
        if (is_gap(phase, mask, k)) {
            usable[k] = 0;
            ++r.gap_samples_;
        }
    }
    r.store_scaled(phase.size(), [&](const auto& each) {
        long double held = 0.0L;
        for (std::size_t k = 0; k < phase.size(); ++k) {
            if (usable[k]) held = static_cast<long double>(phase[k]) - origin;
            each(k, held);
        }
    });
    r.build_segments(usable, linked);
    return r;
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
