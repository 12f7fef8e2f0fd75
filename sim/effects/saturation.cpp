// E14 saturation (saturation.hpp).
#include "sim/effects/saturation.hpp"

#include <algorithm>

namespace driftlab::sim {

void SaturationParams::validate(const TomlReader& r) const {
    const bool analog = stage == "analog";
    const ChannelValues lo = physical_per_channel(min_dps, min_g);
    const ChannelValues hi = physical_per_channel(max_dps, max_g);
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (analog && (std::isfinite(lo[c]) || std::isfinite(hi[c]))) {
            r.fail(std::isfinite(lo[c]) ? (c == 0 ? "min_dps" : "min_g") : (c == 0 ? "max_dps" : "max_g"),
                   "physical range given with stage = \"analog\"; use min_v/max_v [V]");
        }
        if (!analog && (std::isfinite(min_v[c]) || std::isfinite(max_v[c]))) {
            r.fail(std::isfinite(min_v[c]) ? "min_v" : "max_v", "analog rails need stage = \"analog\"");
        }
        if (!(lo[c] < hi[c])) r.fail(c == 0 ? "max_dps" : "max_g", "expected max > min");
        if (!(min_v[c] < max_v[c])) r.fail("max_v", "expected max_v > min_v [V]");
    }
}

void Saturation::apply(ChannelValues& values, const EffectContext& ctx) {
    const ChannelValues lo = analog_ ? p_.min_v : physical_per_channel(p_.min_dps, p_.min_g);
    const ChannelValues hi = analog_ ? p_.max_v : physical_per_channel(p_.max_dps, p_.max_g);
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = first; c < last; ++c) values[c] = std::clamp(values[c], lo[c], hi[c]);
}

}  // namespace driftlab::sim
