// The synthetic sensor chain; see sensor_model.hpp.
#include "sim/model/sensor_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/model/streams.hpp"

namespace driftlab::sim {

namespace {

std::size_t stage_index(Stage s) { return static_cast<std::size_t>(s); }

}  // namespace

ChannelBases base_of(const SimModel& model) {
    const double levels = std::ldexp(1.0, model.adc.bits);
    ChannelBases base;
    for (std::size_t i = 0; i < kChannelCount; ++i) {
        const ChannelModel& ch = model.channels[i];
        const double raw_std_counts =
            ch.raw_noise_std_unit * FrontEnd(ch.front_end, model.adc.vref_v).counts_per_unit(levels);
        base[i] = {ch.drift, analog_sigma_for_raw_std_counts(raw_std_counts)};
    }
    return base;
}

SensorModel::SensorModel(const SimModel& model, std::uint64_t seed, double powered_before_boot_s)
    : SensorModel(model, base_of(model), model.effects, seed, powered_before_boot_s) {}

SensorModel::SensorModel(const SimModel& unit, const ChannelBases& base, const std::vector<EffectSpec>& effects,
                         std::uint64_t seed, double powered_before_boot_s)
    : adc_(unit.adc), powered_before_boot_s_(powered_before_boot_s), mid_counts_(std::ldexp(1.0, unit.adc.bits - 1)) {
    for (std::size_t i = 0; i < kChannelCount; ++i) {
        front_ends_.emplace_back(unit.channels[i].front_end, unit.adc.vref_v);
        drifts_.emplace_back(base[i].drift);
        noise_.emplace_back(base[i].sigma_n_counts, Rng(seed, kNoiseStreamBase + i));
        inputs_unit_[i] = unit.channels[i].input_unit;
    }
    for (const EffectSpec& spec : effects) {
        auto effect = make_effect(spec.name, spec.table, "effects." + spec.name);
        effect->reset(seed);
        // An effect that models no temperature answers NaN at every t, so one instant tells.
        if (temperature_ == nullptr && !std::isnan(effect->temperature_degc(0.0))) temperature_ = effect.get();
        by_stage_[stage_index(effect->stage())].push_back(std::move(effect));
    }
    // The model file's order is the user's, not the physics': within a stage the effect library fixes it
    // (adc_inl before adc_dnl quantises, saturation after the biases it clips).
    for (auto& stage : by_stage_) {
        std::stable_sort(stage.begin(), stage.end(), [](const auto& a, const auto& b) {
            return application_rank(a->name()) < application_rank(b->name());
        });
    }
}

double SensorModel::counts_per_unit(Channel c) const {
    return front_ends_[channel_index(c)].counts_per_unit(std::ldexp(1.0, adc_.params().bits));
}

Conversion SensorModel::convert(Channel c, double board_t_s, const ConversionExtras& extras) {
    const std::size_t i = channel_index(c);
    EffectContext ctx;
    ctx.channel = c;
    ctx.t_s = board_t_s;
    // Timing effects see dt_s = 0: the interval is known only once they have moved the instant.
    for (auto& e : by_stage_[stage_index(Stage::timing)]) ctx.t_s = e->actual_instant_s(ctx.t_s, ctx);
    // However large the jitter, a channel's instant never goes before its previous one (or before power-on), so
    // dt_s >= 0: the processes' sqrt(dt) stays real. Model files keep jitter far smaller (model_file.cpp).
    ctx.t_s = std::max(ctx.t_s + powered_before_boot_s_, last_t_s_[i]);
    if (started_[i])
        ctx.dt_s = ctx.t_s - last_t_s_[i];
    else
        ctx.since_power_on_s = ctx.t_s;
    started_[i] = true;
    last_t_s_[i] = ctx.t_s;
    ChannelValues values = inputs_unit_;
    if (motion_) {
        // The unit's motion is on the board's clock, which runs from the board's start, not the sensor's power-on.
        const ChannelValues moving = motion_(ctx.t_s - powered_before_boot_s_);
        for (std::size_t k = 0; k < kChannelCount; ++k) values[k] += moving[k];
    }
    ctx.true_physical = values;
    if (temperature_ != nullptr) ctx.temperature_degc = temperature_->temperature_degc(ctx.t_s);

    // apply_in_chain gives input effects (vibration) to all four channels' true motion, so cross-couplings
    // (g_sensitivity reads the accel axes while the gyro is converted) see them.
    for (auto& e : by_stage_[stage_index(Stage::physical)]) apply_in_chain(*e, values, ctx);

    const FrontEnd& fe = front_ends_[i];
    values[i] = fe.amplifier_v(fe.sensor_v(values[i]));
    for (auto& e : by_stage_[stage_index(Stage::analog)]) apply_in_chain(*e, values, ctx);

    // Eq. 1 is the at-rest reading, so the chain adds its distance from mid-scale at the converter input.
    const double drift_counts =
        extras.drift_counts ? *extras.drift_counts : drifts_[i].at_counts(ctx.t_s) - mid_counts_;
    values[i] = adc_.counts_from_volts(values[i]) + drift_counts + noise_[i].sample_counts() + extras.added_counts;
    if (extras.quantiser == nullptr)
        for (auto& e : by_stage_[stage_index(Stage::converter)]) apply_in_chain(*e, values, ctx);

    // The converter would read NaN as code 0, a plausible reading on the rail: a broken effect must stop the run.
    if (std::isnan(values[i]))
        throw std::logic_error(std::string("sensor model: ") + kChannelNames[i] +
                               " is NaN at the converter input at t = " + std::to_string(ctx.t_s) +
                               " s (an effect produced it)");
    const std::uint16_t code =
        extras.quantiser ? static_cast<std::uint16_t>((*extras.quantiser)(values[i])) : adc_.convert_counts(values[i]);
    return {code, ctx.t_s};
}

}  // namespace driftlab::sim
