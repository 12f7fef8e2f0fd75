// Candidate effects and their mapping onto the simulator's library; see candidates.hpp.
#include "host/gap/candidates.hpp"

#include <cmath>
#include <stdexcept>

#include "sim/effects/effect.hpp"
#include "sim/model/drift.hpp"

namespace driftlab::host::gap {

namespace {

// Physical-stage effects take a gyro field in deg/s and an accel field as [x, y, z] in g.
void set_channel_value(toml::table& t, const std::string& gyro_key, const std::string& accel_key, Channel c, double v) {
    if (c == Channel::gyro) {
        t.insert_or_assign(gyro_key, v);
    } else {
        toml::array a{0.0, 0.0, 0.0};
        a.get(channel_index(c) - 1)->as_floating_point()->get() = v;
        t.insert_or_assign(accel_key, a);
    }
}

// Per-channel arrays (scalar or 4 values): the other channels keep a harmless default.
toml::array per_channel(Channel c, double v, double others) {
    toml::array a;
    for (std::size_t i = 0; i < kChannelCount; ++i) a.push_back(i == channel_index(c) ? v : others);
    return a;
}

}  // namespace

const std::vector<CandidateInfo>& candidate_list() {
    static const std::vector<CandidateInfo> list = {
        {"thermal_second_tc", {"c3_unit", "t2_s"}, FitRoute::deterministic,
         "log a second power-on after a full cool-down: an exponential repeats at the same T2, a random walk does not"},
        {"ambient_cycle", {"amplitude_unit", "period_s", "phase_rad"}, FitRoute::deterministic,
         "log a board thermistor, or log long enough for 3 cycles: the line at 1/P must be coherent with temperature; "
         "log again at a slightly different sample rate: an aliased mains line moves, a thermal cycle does not"},
        {"gauss_markov", {"sigma_unit", "tau_s"}, FitRoute::spectral,
         "log at least 20 correlation times: one Gauss-Markov gives an ADEV bump less than a decade wide, flicker a plateau"},
        {"flicker", {"b_unit"}, FitRoute::spectral,
         "log longer (>= 1.5 decades of flat ADEV separate flicker from a single Gauss-Markov process)"},
        {"rate_random_walk", {"k_unit_per_sqrt_s"}, FitRoute::spectral,
         "repeat the run: a random walk differs between runs, a thermal exponential repeats"},
        {"spikes", {"rate_hz", "scale_counts"}, FitRoute::simulated,
         "log the RAW codes too: a spike before the smoother is kernel-shaped, a link error is a single sample"},
        {"adc_dnl", {}, FitRoute::code_density,
         "sweep the input slowly through the codes (a code-density test, IEEE 1241): DNL repeats at the same codes, "
         "whatever the noise or the drift"},
    };
    return list;
}

const std::vector<NotIdentifiable>& not_identifiable_list() {
    static const std::vector<NotIdentifiable> list = {
        {"cross_axis", "a static log has constant inputs: misalignment is absorbed in the biases (needs multi-position data)"},
        {"g_sensitivity", "gravity is constant on a static table: the gyro's g-sensitivity is absorbed in its bias (needs tilts)"},
        {"temp_scale_factor", "the true rate is zero at rest: a scale-factor tempco multiplies zero (needs a turntable)"},
        {"vibration", "the table is vibration-isolated: no motion input to identify (needs a shaker or accelerometer reference)"},
        {"saturation", "nothing approaches the rails at rest (needs motion beyond the range)"},
        {"adc_inl", "at rest the code follows time, so INL(code) and a slow drift (time) cannot be separated (needs several offsets)"},
        {"supply_coupling", "no supply channel is logged (log a Vcc divider channel)"},
        {"mains_alias", "aliased mains pickup is a sine in the output, the same shape ambient_cycle fits; from one log at one "
                        "sample rate the two are one candidate (log at a slightly different rate: an alias moves)"},
        {"clock_jitter", "at rest the values hardly change between instants, so a timing error moves them by dy/dt x jitter, "
                         "about nothing; the log's own timestamps are summarised under timing (needs a reference clock for the drift)"},
    };
    return list;
}

std::vector<NotIdentifiable> not_tried_without_raw_codes() {
    std::vector<NotIdentifiable> out;
    for (const auto& info : candidate_list())
        if (info.route == FitRoute::code_density)
            out.push_back({info.effect, "fitted to the raw codes of a raw-mode log (a raw_<channel> column), which this log "
                                        "lacks; on smoothed outputs alone the frac cells locate it, weakly"});
    return out;
}

const CandidateInfo* find_candidate(const std::string& effect) {
    for (const auto& info : candidate_list())
        if (info.effect == effect) return &info;
    return nullptr;
}

const CandidateInfo& candidate(const std::string& effect) {
    if (const CandidateInfo* info = find_candidate(effect)) return *info;
    throw std::invalid_argument("unknown candidate effect: " + effect);
}

std::vector<std::string> candidate_param_names(const std::string& effect, Channel c) {
    const std::string unit = c == Channel::gyro ? "dps" : "g";
    std::vector<std::string> out;
    for (std::string k : candidate(effect).param_keys) {
        const auto pos = k.find("unit");
        if (pos != std::string::npos) k.replace(pos, 4, unit);
        out.push_back(k);
    }
    return out;
}

std::vector<double> model_mean_counts(const GapModel& model, Channel c, const std::vector<double>& t_s) {
    const std::size_t i = channel_index(c);
    const sim::Drift drift(model.base[i].drift);
    std::vector<double> mean(t_s.size());
    for (std::size_t k = 0; k < t_s.size(); ++k) mean[k] = drift.at_counts(t_s[k]);
    const double cpu = counts_per_unit(model, c);
    for (const sim::EffectSpec& spec : model.effects) {
        const CandidateInfo* info = find_candidate(spec.name);
        if (!info || info->route != FitRoute::deterministic) continue;
        const auto effect = sim::make_effect(spec.name, spec.table, "effects." + spec.name);
        effect->reset(0);
        sim::EffectContext ctx;
        ctx.channel = c;
        for (std::size_t k = 0; k < t_s.size(); ++k) {
            ctx.dt_s = k ? t_s[k] - t_s[k - 1] : 0.0;
            ctx.t_s = t_s[k];
            sim::ChannelValues values{};
            effect->apply(values, ctx);
            mean[k] += values[i] * cpu;
        }
    }
    return mean;
}

sim::EffectSpec make_candidate_effect(const std::string& effect, Channel c, const std::vector<double>& p,
                                      const GapModel& model) {
    sim::EffectSpec spec;
    spec.name = effect;
    toml::table& t = spec.table;
    if (effect == "thermal_second_tc") {
        set_channel_value(t, "c3_dps", "c3_g", c, p.at(0));
        t.insert_or_assign("t2_s", per_channel(c, p.at(1), 1800.0));
    } else if (effect == "ambient_cycle") {
        // A sine of 2 K peak to peak with no lag: the coupling is then the amplitude per kelvin.
        t.insert_or_assign("waveform", "sine");
        t.insert_or_assign("amplitude_k_pp", 2.0);
        t.insert_or_assign("period_s", p.at(1));
        t.insert_or_assign("phase_rad", p.at(2));
        t.insert_or_assign("lag_s", 0.0);
        set_channel_value(t, "coupling_dps_per_k", "coupling_g_per_k", c, p.at(0));
    } else if (effect == "gauss_markov") {
        set_channel_value(t, "sigma_dps", "sigma_g", c, p.at(0));
        t.insert_or_assign("tau_s", per_channel(c, p.at(1), 100.0));
    } else if (effect == "flicker") {
        // The 1/f band spans the log: from below its length to a tenth of the sampling rate (flicker.hpp).
        set_channel_value(t, "b_dps", "b_g", c, p.at(0));
        const double fs = 1.0 / model.smoothing.sample_period_s;
        t.insert_or_assign("f_high_hz", fs / 10.0);
        t.insert_or_assign("f_low_hz", fs * 1e-5);
    } else if (effect == "rate_random_walk") {
        set_channel_value(t, "k_dps_per_sqrt_s", "k_g_per_sqrt_s", c, p.at(0));
    } else if (effect == "spikes") {
        t.insert_or_assign("stage", "converter");
        t.insert_or_assign("rate_hz", per_channel(c, p.at(0), 0.0));
        t.insert_or_assign("scale_counts", per_channel(c, p.at(1), 0.0));
    } else {
        throw std::invalid_argument("unknown candidate effect: " + effect);
    }
    return spec;
}

}  // namespace driftlab::host::gap
