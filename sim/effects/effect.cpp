// Effect interface defaults, stage names and RNG substream ids (effect.hpp).
#include "sim/effects/effect.hpp"

namespace driftlab::sim {

const char* stage_name(Stage stage) {
    switch (stage) {
    case Stage::physical: return "physical";
    case Stage::analog: return "analog";
    case Stage::converter: return "converter";
    case Stage::timing: return "timing";
    }
    return "?";
}

double Effect::actual_instant_s(double nominal_s, const EffectContext&) { return nominal_s; }

void apply_in_chain(Effect& effect, ChannelValues& values, EffectContext& ctx) {
    if (!effect.is_input()) {
        effect.apply(values, ctx);
        return;
    }
    EffectContext all = ctx;
    all.channel.reset();
    ChannelValues motion{};
    effect.apply(motion, all);
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        ctx.true_physical[c] += motion[c];
        if (!ctx.channel || channel_index(*ctx.channel) == c) values[c] += motion[c];
    }
}

std::uint64_t effect_stream_id(std::string_view name, std::size_t channel) {
    // FNV-1a of the name: stable across builds and independent of which other effects exist.
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (char c : name) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001b3ull;
    }
    return h * 8u + channel;
}

}  // namespace driftlab::sim
