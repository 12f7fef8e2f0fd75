// The effect registry: one table maps name -> stage -> factory, so model files, JSON and docs share the names.
#include <algorithm>
#include <functional>

#include "sim/effects/adc_dnl.hpp"
#include "sim/effects/adc_inl.hpp"
#include "sim/effects/ambient_cycle.hpp"
#include "sim/effects/bandwidth.hpp"
#include "sim/effects/clock_jitter.hpp"
#include "sim/effects/cross_axis.hpp"
#include "sim/effects/effect.hpp"
#include "sim/effects/flicker.hpp"
#include "sim/effects/g_sensitivity.hpp"
#include "sim/effects/gauss_markov.hpp"
#include "sim/effects/mains_alias.hpp"
#include "sim/effects/params.hpp"
#include "sim/effects/rate_random_walk.hpp"
#include "sim/effects/saturation.hpp"
#include "sim/effects/scale_factor.hpp"
#include "sim/effects/spikes.hpp"
#include "sim/effects/supply_coupling.hpp"
#include "sim/effects/temp_scale_factor.hpp"
#include "sim/effects/thermal_second_tc.hpp"
#include "sim/effects/vibration.hpp"

namespace driftlab::sim {
namespace {

struct Entry {
    EffectInfo info;
    std::function<std::unique_ptr<Effect>(const toml::table&, std::string_view)> make;
};

template <class E>
Entry entry() {
    using Params = typename E::Params;
    return {EffectInfo{std::string(E::kName), E::kStage, std::string(E::kEquation), std::string(E::kSummary),
                       describe_params<Params>()},
            [](const toml::table& table, std::string_view key_path) -> std::unique_ptr<Effect> {
                return std::make_unique<E>(params_from_toml<Params>(table, key_path));
            }};
}

const std::vector<Entry>& entries() {
    static const std::vector<Entry> table = [] {
        // Recommended application order within a stage (list_effects() keeps it): input motion first, then
        // additive biases, couplings on the true input, clipping last; INL shifts transitions before DNL quantises;
        // bit-flip spikes act on the quantised code.
        return std::vector<Entry>{
            entry<Vibration>(),      entry<ThermalSecondTc>(), entry<AmbientCycle>(), entry<Flicker>(),
            entry<RateRandomWalk>(), entry<GaussMarkov>(),     entry<ScaleFactor>(),  entry<TempScaleFactor>(),
            entry<CrossAxis>(),      entry<GSensitivity>(),    entry<Bandwidth>(),    entry<Saturation>(),
            entry<SupplyCoupling>(), entry<MainsAlias>(),      entry<AdcInl>(),       entry<AdcDnl>(),
            entry<Spikes>(),         entry<ClockJitter>(),
        };
    }();
    return table;
}

const Entry* lookup(std::string_view name) {
    const auto& t = entries();
    const auto it = std::find_if(t.begin(), t.end(), [&](const Entry& e) { return e.info.name == name; });
    return it == t.end() ? nullptr : &*it;
}

}  // namespace

const std::vector<EffectInfo>& list_effects() {
    static const std::vector<EffectInfo> infos = [] {
        std::vector<EffectInfo> v;
        for (const Entry& e : entries()) v.push_back(e.info);
        return v;
    }();
    return infos;
}

bool is_effect_name(std::string_view name) { return lookup(name) != nullptr; }

std::size_t application_rank(std::string_view name) {
    const Entry* e = lookup(name);
    return e == nullptr ? entries().size() : static_cast<std::size_t>(e - entries().data());
}

std::unique_ptr<Effect> make_effect(std::string_view name, const toml::table& table, std::string_view key_path) {
    const Entry* e = lookup(name);
    if (e == nullptr) {
        std::string known;
        for (const Entry& x : entries()) known += (known.empty() ? "" : ", ") + x.info.name;
        throw ConfigError(std::string(key_path), table.source().begin.line,
                          "unknown effect \"" + std::string(name) + "\"; known: " + known);
    }
    std::unique_ptr<Effect> effect = e->make(table, key_path);
    effect->reset(0);
    return effect;
}

std::unique_ptr<Effect> make_effect(std::string_view name) { return make_effect(name, toml::table{}, name); }

}  // namespace driftlab::sim
