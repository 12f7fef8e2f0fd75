// E15 spikes (spikes.hpp).
#include "sim/effects/spikes.hpp"

#include <algorithm>

namespace driftlab::sim {

void SpikesParams::validate(const TomlReader& r) const {
    const bool analog = stage == "analog";
    if (analog && distribution == "bit_flip") r.fail("distribution", "bit_flip needs stage = \"converter\"");
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (analog && scale_counts[c] != 0.0) r.fail("scale_counts", "stage \"analog\" takes scale_v [V]");
        if (!analog && scale_v[c] != 0.0) r.fail("scale_v", "stage \"converter\" takes scale_counts [counts]");
    }
    if (student_dof < 1 || student_dof > 100) r.fail("student_dof", "expected 1..100");
}

Spikes::Spikes(const Params& params)
    : EffectWith(params),
      analog_(params.stage == "analog"),
      distribution_(params.distribution == "student_t"  ? Distribution::student_t
                    : params.distribution == "bit_flip" ? Distribution::bit_flip
                                                        : Distribution::gaussian) {
    reset(0);
}

void Spikes::reset(std::uint64_t seed) {
    rng_.clear();
    for (std::size_t c = 0; c < kChannelCount; ++c) rng_.emplace_back(seed, effect_stream_id(kName, c));
}

double Spikes::amplitude(std::size_t channel) {
    Rng& rng = rng_[channel];
    const double scale = analog_ ? p_.scale_v[channel] : p_.scale_counts[channel];
    if (distribution_ == Distribution::student_t) {
        double chi2 = 0.0;  // sum of nu squared normals; only drawn when a spike happens
        for (std::uint64_t i = 0; i < p_.student_dof; ++i) {
            const double z = rng.normal();
            chi2 += z * z;
        }
        return scale * rng.normal() / std::sqrt(chi2 / static_cast<double>(p_.student_dof));
    }
    return scale * rng.normal();
}

void Spikes::apply(ChannelValues& values, const EffectContext& ctx) {
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = first; c < last; ++c) {
        if (p_.rate_hz[c] <= 0.0) continue;
        const double p = -std::expm1(-p_.rate_hz[c] * ctx.dt_s);
        if (rng_[c].uniform() >= p) continue;
        if (distribution_ == Distribution::bit_flip) {
            const auto code = static_cast<std::int64_t>(std::clamp(std::round(values[c]), 0.0, 1023.0));
            const auto bit = static_cast<int>(rng_[c].uniform() * 10.0);
            values[c] = static_cast<double>(code ^ (std::int64_t{1} << bit));
        } else {
            values[c] += amplitude(c);
        }
    }
}

}  // namespace driftlab::sim
