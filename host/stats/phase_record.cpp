// PhaseRecord: rate or phase samples -> phase plus gap-free segments (docs/allan.md §2).
#include "host/stats/phase_record.hpp"

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

PhaseRecord PhaseRecord::from_rate(std::span<const double> rate, double tau0_s,
                                   std::span<const std::uint8_t> mask) {
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
    r.phase_.resize(rate.size() + 1);
    std::vector<std::uint8_t> usable(rate.size() + 1, 1);
    std::vector<std::uint8_t> linked(rate.size(), 1);
    long double x = 0.0L;
    r.phase_[0] = 0.0;
    for (std::size_t k = 0; k < rate.size(); ++k) {
        if (is_gap(rate, mask, k)) {
            linked[k] = 0;
        } else {
            x += (static_cast<long double>(rate[k]) - mean) * tau0_s;
        }
        r.phase_[k + 1] = static_cast<double>(x);
    }
    r.build_segments(usable, linked);
    return r;
}

PhaseRecord PhaseRecord::from_phase(std::span<const double> phase, double tau0_s,
                                    std::span<const std::uint8_t> mask) {
    check_arguments(phase.size(), tau0_s, mask);
    PhaseRecord r;
    r.tau0_s_ = tau0_s;
    r.kind_ = InputKind::phase;

    std::vector<std::uint8_t> usable(phase.size(), 1);
    std::vector<std::uint8_t> linked(phase.empty() ? 0 : phase.size() - 1, 1);
    double origin = 0.0;
    for (std::size_t k = 0; k < phase.size(); ++k) {
        if (!is_gap(phase, mask, k)) {
            origin = phase[k];
            break;
        }
    }
    // Referencing to the first valid sample keeps magnitudes small; gap samples hold the previous value so
    // that sliding sums stay finite (their terms are skipped).
    r.phase_.resize(phase.size());
    double held = 0.0;
    for (std::size_t k = 0; k < phase.size(); ++k) {
        if (is_gap(phase, mask, k)) {
            usable[k] = 0;
            ++r.gap_samples_;
        } else {
            held = phase[k] - origin;
        }
        r.phase_[k] = held;
    }
    r.build_segments(usable, linked);
    return r;
}

void PhaseRecord::build_segments(const std::vector<std::uint8_t>& usable,
                                 const std::vector<std::uint8_t>& linked) {
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
