// The board's smoothed outputs without the link; see board_outputs.hpp.
#include "sim/model/board_outputs.hpp"

#include <algorithm>
#include <cmath>

#include "driftlab/proto/q8_counts.hpp"
#include "firmware/core/ls_window.hpp"
#include "sim/model/drift.hpp"
#include "sim/model/sensor.hpp"

namespace driftlab::sim {

double counts_per_unit(const OutputModel& model, Channel c) {
    const FrontEnd fe(model.unit.channels[channel_index(c)].front_end, model.unit.adc.vref_v);
    return fe.counts_per_unit(std::ldexp(1.0, model.unit.adc.bits));
}

namespace {

// Calls conversion(k, nominal_s) for each conversion instant that can change an output, in time order, and output(k)
// after output k's: the window holds the last N conversions, and older ones cannot change the output, so only those
// are simulated (all of them when N exceeds the conversions per output).
template <class OnConversion, class OnOutput>
void for_each_conversion(const std::vector<double>& t_s, const Smoothing& sm, OnConversion conversion,
                         OnOutput output) {
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

bool has_timing_effect(const std::vector<EffectSpec>& effects) {
    return std::any_of(effects.begin(), effects.end(), [](const EffectSpec& spec) {
        return make_effect(spec.name, spec.table, "effects." + spec.name)->stage() == Stage::timing;
    });
}

}  // namespace

std::optional<DriftAtConversions> drift_at_conversions(const OutputModel& model, const std::vector<double>& t_s,
                                                       const std::array<bool, kChannelCount>& channels,
                                                       std::size_t max_bytes) {
    if (has_timing_effect(model.effects)) return std::nullopt;
    // About as many conversions per channel as outputs times the new conversions per output (a window's at most).
    const std::size_t per_channel =
        t_s.size() *
        static_cast<std::size_t>(std::max(1, std::min(model.smoothing.window, model.smoothing.conversions_per_output)));
    const auto requested = static_cast<std::size_t>(std::count(channels.begin(), channels.end(), true));
    if (requested * per_channel * sizeof(double) > max_bytes) return std::nullopt;
    const double mid_counts = std::ldexp(1.0, model.unit.adc.bits - 1);
    DriftAtConversions out;
    for (std::size_t i = 0; i < kChannelCount; ++i) {
        if (!channels[i]) continue;
        const Drift drift(model.base[i].drift);
        std::vector<double>& d = out[i];
        d.reserve(per_channel);
        for_each_conversion(
            t_s, model.smoothing,
            [&](std::size_t, double nominal_s) { d.push_back(drift.at_counts(nominal_s) - mid_counts); },
            [](std::size_t) {});
    }
    return out;
}

Outputs simulate_outputs(const OutputModel& model, const OutputRequest& request, std::uint64_t seed) {
    Outputs out;
    const std::vector<double>& t_s = *request.t_s;
    const Smoothing& sm = model.smoothing;
    const auto order = sm.fit_order == 1 ? fw::FitOrder::line : fw::FitOrder::mean;
    // Every channel keeps its own state and substreams in the chain, so converting one channel after another gives
    // each the codes of the board's round robin at the same instants.
    SensorModel sensor(model.unit, model.base, model.effects, seed);
    for (std::size_t i = 0; i < kChannelCount; ++i) {
        if (!request.channels[i]) continue;
        const Channel c = static_cast<Channel>(i);
        const std::vector<double>& added = request.added_counts[i];
        ConversionExtras extras;
        if (request.quantiser[i]) extras.quantiser = &request.quantiser[i];
        const std::vector<double>* cached_drift =
            request.drift && !(*request.drift)[i].empty() ? &(*request.drift)[i] : nullptr;
        std::size_t conversion_index = 0;
        fw::LsWindow window;
        window.reset(static_cast<std::uint8_t>(sm.window));
        std::vector<double>& y = out[i];
        y.resize(t_s.size());
        std::vector<double>* raw = request.raw_codes ? &(*request.raw_codes)[i] : nullptr;
        if (raw) raw->resize(t_s.size());
        double newest = 0.0;
        for_each_conversion(
            t_s, sm,
            [&](std::size_t k, double nominal_s) {
                extras.added_counts = added.empty() ? 0.0 : added[k];
                extras.drift_counts = cached_drift ? &(*cached_drift)[conversion_index++] : nullptr;
                const std::uint16_t code = sensor.convert(c, nominal_s, extras).code;
                window.push(code);
                newest = code;
            },
            [&](std::size_t k) {
                y[k] = proto::q8_to_counts(window.estimate_q8(order));
                if (raw) (*raw)[k] = newest;
            });
    }
    return out;
}

}  // namespace driftlab::sim
