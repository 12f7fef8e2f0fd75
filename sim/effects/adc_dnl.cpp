// E6 adc_dnl (adc_dnl.hpp).
#include "sim/effects/adc_dnl.hpp"

#include <algorithm>

#include "sim/model/rng.hpp"

namespace driftlab::sim {

AdcDnl::AdcDnl(const Params& params) : EffectWith(params) {
    active_ = p_.dnl_rms_lsb > 0.0 || !p_.missing_codes.empty() || (p_.carry_bits > 0 && p_.carry_dnl_lsb != 0.0) ||
              !p_.transition_codes.empty();
    // Widths of the inner codes 1..1022; the end codes are open.
    constexpr int kInner = kCodeCount - 2;
    std::vector<double> width(kInner + 1, 1.0);  // index = code, [0] unused
    Rng rng(p_.pattern_seed, effect_stream_id(kName, 0));
    const std::int64_t carry_period = p_.carry_bits > 0 ? (std::int64_t{1} << p_.carry_bits) : 0;
    double sum = 0.0;
    for (int j = 1; j <= kInner; ++j) {
        double dnl = p_.dnl_rms_lsb * rng.normal();
        if (carry_period > 0 && j % carry_period == 0) dnl += p_.carry_dnl_lsb;
        width[static_cast<std::size_t>(j)] = std::max(0.0, 1.0 + dnl);
    }
    for (std::int64_t m : p_.missing_codes) width[static_cast<std::size_t>(m)] = 0.0;
    for (int j = 1; j <= kInner; ++j) sum += width[static_cast<std::size_t>(j)];
    const double scale = sum > 0.0 ? kInner / sum : 1.0;
    transitions_.resize(kCodeCount - 1);
    double t = 0.5;
    for (int j = 1; j < kCodeCount; ++j) {
        transitions_[static_cast<std::size_t>(j - 1)] = t;
        if (j <= kInner) t += width[static_cast<std::size_t>(j)] * scale;
    }
    transitions_.back() = kCodeCount - 1.5;  // exact despite rounding in the running sum
    for (std::size_t k = 0; k < p_.transition_codes.size(); ++k)
        transitions_[static_cast<std::size_t>(p_.transition_codes[k] - 1)] = p_.transition_counts[k];
    // A listed transition beyond a neighbour of the random pattern would make codes overlap.
    std::sort(transitions_.begin(), transitions_.end());
}

int AdcDnl::code_of(double x_counts) const {
    return static_cast<int>(std::upper_bound(transitions_.begin(), transitions_.end(), x_counts) -
                            transitions_.begin());
}

void AdcDnl::apply(ChannelValues& values, const EffectContext& ctx) {
    if (!active_) return;
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = first; c < last; ++c) values[c] = code_of(values[c]);
}

}  // namespace driftlab::sim
