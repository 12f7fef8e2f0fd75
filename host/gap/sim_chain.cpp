// One simulated log of the calibrated model; see sim_chain.hpp.
#include "host/gap/sim_chain.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "firmware/core/ls_window.hpp"
#include "sim/effects/effect.hpp"
#include "sim/model/adc.hpp"
#include "sim/model/rng.hpp"
#include "sim/model/sensor.hpp"
#include "sim/model/streams.hpp"

namespace driftlab::host::gap {

double counts_per_unit(const GapModel& model, Channel c) {
    const sim::FrontEnd fe(model.unit.channels[channel_index(c)].front_end, model.unit.adc.vref_v);
    return fe.counts_per_unit(std::ldexp(1.0, model.unit.adc.bits));
}

namespace {

using EffectList = std::vector<std::unique_ptr<sim::Effect>>;

std::array<EffectList, 4> build_effects(const GapModel& model, std::uint64_t seed) {
    std::array<EffectList, 4> by_stage;
    for (const sim::EffectSpec& spec : model.effects) {
        auto effect = sim::make_effect(spec.name, spec.table, "effects." + spec.name);
        effect->reset(seed);
        by_stage[static_cast<std::size_t>(effect->stage())].push_back(std::move(effect));
    }
    return by_stage;
}

// Calls conversion(k, nominal_s) for each conversion instant that can change an output, in time order, and output(k)
// after output k's: the window holds the last N conversions, and older ones cannot change the output, so only those
// are simulated (all of them when N exceeds the conversions per output).
template <class Conversion, class Output>
void for_each_conversion(const std::vector<double>& t_s, const Smoothing& sm, Conversion conversion, Output output) {
    const double conversion_period_s = sm.conversion_period_s();
    double last_instant_s = -1e300;
    for (std::size_t k = 0; k < t_s.size(); ++k) {
        for (int j = sm.window - 1; j >= 0; --j) {
            const double nominal_s = t_s[k] - j * conversion_period_s;
            if (nominal_s <= last_instant_s) continue;
            last_instant_s = nominal_s;
            conversion(k, nominal_s);
        }
        output(k);
    }
}

}  // namespace

std::optional<DriftAtConversions> drift_at_conversions(const GapModel& model, const std::vector<double>& t_s,
                                                       const std::array<bool, kChannelCount>& channels,
                                                       std::size_t max_bytes) {
    for (const sim::EffectSpec& spec : model.effects)
        if (sim::make_effect(spec.name, spec.table, "effects." + spec.name)->stage() == sim::Stage::timing) return std::nullopt;
    // About as many conversions per channel as outputs times the new conversions per output (a window's at most).
    const std::size_t per_channel =
        t_s.size() * static_cast<std::size_t>(std::max(1, std::min(model.smoothing.window, model.smoothing.conversions_per_output)));
    const auto requested = static_cast<std::size_t>(std::count(channels.begin(), channels.end(), true));
    if (requested * per_channel * sizeof(double) > max_bytes) return std::nullopt;
    const double mid_counts = std::ldexp(1.0, model.unit.adc.bits - 1);
    DriftAtConversions out;
    for (std::size_t i = 0; i < kChannelCount; ++i) {
        if (!channels[i]) continue;
        const sim::Drift drift(model.base[i].drift);
        std::vector<double>& d = out[i];
        d.reserve(per_channel);
        for_each_conversion(
            t_s, model.smoothing, [&](std::size_t, double nominal_s) { d.push_back(drift.at_counts(nominal_s) - mid_counts); },
            [](std::size_t) {});
    }
    return out;
}

SimOutput simulate(const GapModel& model, const SimRequest& request, std::uint64_t seed) {
    SimOutput out;
    const std::vector<double>& t_s = *request.t_s;
    const sim::Adc adc(model.unit.adc);
    const double mid_counts = std::ldexp(1.0, model.unit.adc.bits - 1);
    const Smoothing& sm = model.smoothing;
    const auto order = sm.fit_order == 1 ? fw::FitOrder::line : fw::FitOrder::mean;
    auto effects = build_effects(model, seed);
    const auto& physical = effects[static_cast<std::size_t>(sim::Stage::physical)];
    const auto& analog = effects[static_cast<std::size_t>(sim::Stage::analog)];
    const auto& converter = effects[static_cast<std::size_t>(sim::Stage::converter)];
    const auto& timing = effects[static_cast<std::size_t>(sim::Stage::timing)];

    for (std::size_t i = 0; i < kChannelCount; ++i) {
        if (!request.channels[i]) continue;
        const Channel c = static_cast<Channel>(i);
        const sim::ChannelModel& ch = model.unit.channels[i];
        const sim::FrontEnd fe(ch.front_end, model.unit.adc.vref_v);
        const sim::Drift drift(model.base[i].drift);
        const double sigma = model.base[i].sigma_n_counts;
        sim::Rng noise(seed, sim::kNoiseStreamBase + i);
        const std::vector<double>& added = request.added_counts[i];
        const Quantiser& quantiser = request.quantiser[i];
        const std::vector<double>* cached_drift = request.drift && !(*request.drift)[i].empty() ? &(*request.drift)[i] : nullptr;
        std::size_t conversion_index = 0;
        fw::LsWindow window;
        window.reset(static_cast<std::uint8_t>(sm.window));
        double last_actual_s = 0.0;
        bool started = false;
        std::vector<double>& y = out[i];
        y.resize(t_s.size());
        std::vector<double>* raw = request.raw_codes ? &(*request.raw_codes)[i] : nullptr;
        if (raw) raw->resize(t_s.size());
        double newest = 0.0;
        for_each_conversion(
            t_s, sm,
            [&](std::size_t k, double nominal_s) {
                sim::EffectContext ctx;
                ctx.channel = c;
                ctx.t_s = nominal_s;
                for (auto& e : timing) ctx.t_s = e->actual_instant_s(ctx.t_s, ctx);
                ctx.dt_s = started ? ctx.t_s - last_actual_s : 0.0;
                started = true;
                last_actual_s = ctx.t_s;
                sim::ChannelValues values{};
                for (std::size_t m = 0; m < kChannelCount; ++m) values[m] = model.unit.channels[m].input_unit;
                ctx.true_physical = values;
                for (auto& e : physical) e->apply(values, ctx);
                values[i] = fe.amplifier_v(fe.sensor_v(values[i]));
                for (auto& e : analog) e->apply(values, ctx);
                const double drift_counts = cached_drift ? (*cached_drift)[conversion_index++] : drift.at_counts(ctx.t_s) - mid_counts;
                values[i] = adc.counts_from_volts(values[i]) + drift_counts + sigma * noise.normal() +
                            (added.empty() ? 0.0 : added[k]);
                std::uint16_t code = 0;
                if (quantiser) {
                    code = static_cast<std::uint16_t>(quantiser(values[i]));
                } else {
                    for (auto& e : converter) e->apply(values, ctx);
                    code = adc.convert_counts(values[i]);
                }
                window.push(code);
                newest = code;
            },
            [&](std::size_t k) {
                y[k] = window.estimate_q8(order) / 256.0;
                if (raw) (*raw)[k] = newest;
            });
    }
    return out;
}

}  // namespace driftlab::host::gap
