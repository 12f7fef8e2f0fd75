// Random-number discipline of the effects: one substream per effect and channel, so switching an effect on leaves
// the others' draws unchanged; a seed reproduces a run; per-conversion and per-sample use give a channel the same
// sequence.
#include <set>

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

std::vector<std::unique_ptr<Effect>> build(const std::vector<std::pair<std::string, std::string>>& specs,
                                           std::uint64_t seed) {
    std::vector<std::unique_ptr<Effect>> out;
    for (const auto& [name, text] : specs) {
        out.push_back(test::effect_from(name, text));
        out.back()->reset(seed);
    }
    return out;
}

// Channel series of what a list of effects adds to zero, applied in order per instant.
std::vector<ChannelValues> run(std::vector<std::unique_ptr<Effect>>& effects, std::size_t n, double dt_s) {
    std::vector<ChannelValues> out;
    for (std::size_t k = 0; k < n; ++k) {
        EffectContext ctx;
        ctx.t_s = static_cast<double>(k) * dt_s;
        ctx.dt_s = k == 0 ? 0.0 : dt_s;
        ChannelValues v{};
        for (auto& e : effects) e->apply(v, ctx);
        out.push_back(v);
    }
    return out;
}

const std::pair<std::string, std::string> kGm{"gauss_markov", "sigma_dps = 0.1\nsigma_g = 0.01\ntau_s = 5.0"};
const std::pair<std::string, std::string> kFlicker{"flicker", "b_dps = 0.05\nb_g = 0.01"};
const std::pair<std::string, std::string> kSpikes{"spikes", "rate_hz = 1.0\nscale_counts = 5.0"};
const std::pair<std::string, std::string> kRrw{"rate_random_walk", "k_dps_per_sqrt_s = 0.01\nk_g_per_sqrt_s = 0.01"};

TEST(EffectSubstreams, SwitchingOtherEffectsOnLeavesGaussMarkovDrawsUnchanged) {
    auto alone = build({kGm}, 99);
    auto others = build({kFlicker, kSpikes, kRrw}, 99);
    auto all = build({kFlicker, kSpikes, kGm, kRrw}, 99);
    const auto a = run(alone, 2000, 0.1), o = run(others, 2000, 0.1), b = run(all, 2000, 0.1);
    for (std::size_t k = 0; k < a.size(); ++k)
        for (std::size_t c = 0; c < kChannelCount; ++c) EXPECT_NEAR(b[k][c] - o[k][c], a[k][c], 1e-12);
}

TEST(EffectSubstreams, SameSeedReproducesAndAnotherSeedDiffers) {
    auto first = build({kGm, kFlicker, kSpikes, kRrw}, 5);
    auto second = build({kGm, kFlicker, kSpikes, kRrw}, 5);
    auto third = build({kGm, kFlicker, kSpikes, kRrw}, 6);
    const auto a = run(first, 500, 0.1), b = run(second, 500, 0.1), c = run(third, 500, 0.1);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    // reset() restarts the same run.
    for (auto& e : first) e->reset(5);
    EXPECT_EQ(run(first, 500, 0.1), b);
}

TEST(EffectSubstreams, PerConversionGivesEachChannelItsPerSampleSequence) {
    auto per_sample = build({kGm, kFlicker, kRrw}, 11);
    auto per_conversion = build({kGm, kFlicker, kRrw}, 11);
    const auto a = run(per_sample, 300, 0.04);
    for (std::size_t k = 0; k < 300; ++k) {
        for (std::size_t c : {2u, 0u, 3u, 1u}) {  // any round-robin order
            EffectContext ctx;
            ctx.channel = static_cast<Channel>(c);
            ctx.t_s = static_cast<double>(k) * 0.04;
            ctx.dt_s = k == 0 ? 0.0 : 0.04;
            ChannelValues v{};
            for (auto& e : per_conversion) e->apply(v, ctx);
            EXPECT_EQ(v[c], a[k][c]);
            for (std::size_t other = 0; other < kChannelCount; ++other) {
                if (other != c) {
                    EXPECT_EQ(v[other], 0.0);
                }
            }
        }
    }
}

TEST(EffectSubstreams, StreamIdsAreDistinctAcrossEffectsAndChannels) {
    std::set<std::uint64_t> ids;
    for (const EffectInfo& info : list_effects())
        for (std::size_t c = 0; c <= kChannelCount; ++c) ids.insert(effect_stream_id(info.name, c));
    EXPECT_EQ(ids.size(), list_effects().size() * (kChannelCount + 1));
}

}  // namespace
}  // namespace driftlab::sim
