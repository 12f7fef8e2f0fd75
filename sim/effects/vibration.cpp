// E11 vibration (vibration.hpp).
#include "sim/effects/vibration.hpp"

#include <numbers>

namespace driftlab::sim {

void VibrationParams::validate(const TomlReader& r) const {
    const std::pair<const char*, const std::vector<double>*> per_tone[] = {{"tone_dps", &tone_dps},
                                                                           {"tone_g_x", &tone_g_x},
                                                                           {"tone_g_y", &tone_g_y},
                                                                           {"tone_g_z", &tone_g_z},
                                                                           {"tone_phase_rad", &tone_phase_rad}};
    for (const auto& [key, v] : per_tone) {
        if (!v->empty() && v->size() != tone_hz.size()) {
            r.fail(key, "expected " + std::to_string(tone_hz.size()) + " values (one per tone_hz), got " +
                            std::to_string(v->size()));
        }
    }
    if (!(band_high_hz > band_low_hz)) r.fail("band_high_hz", "expected band_high_hz > band_low_hz [Hz]");
    if (random_lines == 0 || random_lines > 4096) r.fail("random_lines", "expected 1..4096 lines");
}

double Vibration::tone_amplitude(std::size_t channel, std::size_t tone) const {
    const std::vector<double>* amps[kChannelCount] = {&p_.tone_dps, &p_.tone_g_x, &p_.tone_g_y, &p_.tone_g_z};
    return tone < amps[channel]->size() ? (*amps[channel])[tone] : 0.0;
}

void Vibration::reset(std::uint64_t seed) {
    const ChannelValues rms = physical_per_channel(p_.random_rms_dps, p_.random_rms_g);
    const std::size_t k = static_cast<std::size_t>(p_.random_lines);
    lines_.assign(kChannelCount * k, Line{0.0, 0.0});
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (rms[c] <= 0.0) continue;
        Rng rng(seed, effect_stream_id(kName, c));
        for (std::size_t i = 0; i < k; ++i) {
            const double f = p_.band_low_hz + (p_.band_high_hz - p_.band_low_hz) * rng.uniform();
            lines_[c * k + i] = {f, 2.0 * std::numbers::pi * rng.uniform()};
        }
    }
}

void Vibration::apply(ChannelValues& values, const EffectContext& ctx) {
    const ChannelValues rms = physical_per_channel(p_.random_rms_dps, p_.random_rms_g);
    const std::size_t k = static_cast<std::size_t>(p_.random_lines);
    const double two_pi_t = 2.0 * std::numbers::pi * ctx.t_s;
    const auto [first, last] = channels_of(ctx);
    for (std::size_t c = first; c < last; ++c) {
        double sum = 0.0;
        for (std::size_t m = 0; m < p_.tone_hz.size(); ++m) {
            const double a = tone_amplitude(c, m);
            const double phase = m < p_.tone_phase_rad.size() ? p_.tone_phase_rad[m] : 0.0;
            if (a != 0.0) sum += a * std::sin(two_pi_t * p_.tone_hz[m] + phase);
        }
        if (rms[c] > 0.0) {
            const double a = rms[c] * std::sqrt(2.0 / static_cast<double>(k));
            for (std::size_t i = 0; i < k; ++i) {
                sum += a * std::sin(two_pi_t * lines_[c * k + i].frequency_hz + lines_[c * k + i].phase_rad);
            }
        }
        values[c] += sum;
    }
}

}  // namespace driftlab::sim
