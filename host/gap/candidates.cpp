// Candidate effects and their mapping onto the simulator's library; see candidates.hpp.
#include "host/gap/candidates.hpp"

#include <cmath>
#include <stdexcept>

#include "sim/effects/effect.hpp"
#include "sim/effects/flicker.hpp"
#include "sim/model/drift.hpp"

namespace driftlab::host::gap {

namespace {

// The key of a mean shape's or Gaussian process's size in its library table: the gyro's, and the accel axes' array.
struct SizeKeys {
    const char* effect;
    const char* gyro;
    const char* accel;
};
constexpr SizeKeys kSizeKeys[] = {
    {"thermal_second_tc", "c3_dps", "c3_g"},
    {"ambient_cycle", "coupling_dps_per_k", "coupling_g_per_k"},
    {"gauss_markov", "sigma_dps", "sigma_g"},
    {"flicker", "b_dps", "b_g"},
    {"rate_random_walk", "k_dps_per_sqrt_s", "k_g_per_sqrt_s"},
};

const SizeKeys* size_keys(const std::string& effect) {
    for (const SizeKeys& k : kSizeKeys)
        if (effect == k.effect) return &k;
    return nullptr;
}

// Channel c's size in a library table as the library writes it (accel sizes an array of three), or null.
toml::value<double>* size_value(toml::table& t, const SizeKeys& k, Channel c) {
    toml::node* n = t.get(c == Channel::gyro ? k.gyro : k.accel);
    if (n && c != Channel::gyro) n = n->is_array() ? n->as_array()->get(channel_index(c) - 1) : nullptr;
    return n ? n->as_floating_point() : nullptr;
}

// A candidate's size on channel c alone: physical-stage effects take a gyro field in deg/s and an accel field as
// [x, y, z] in g.
void set_size(toml::table& t, const std::string& effect, Channel c, double v) {
    const SizeKeys& k = *size_keys(effect);
    if (c == Channel::gyro) {
        t.insert_or_assign(k.gyro, v);
    } else {
        toml::array a{0.0, 0.0, 0.0};
        a.get(channel_index(c) - 1)->as_floating_point()->get() = v;
        t.insert_or_assign(k.accel, a);
    }
}

// The library's full table of `spec`: every key, scalars broadcast as the effect reads them.
toml::table full_table(const sim::EffectSpec& spec) {
    return sim::make_effect(spec.name, spec.table, "effects." + spec.name)->parameters();
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
        {"thermal_second_tc",
         {"c3_unit", "t2_s"},
         FitRoute::deterministic,
         "log a second power-on after a full cool-down: an exponential repeats at the same T2, a random walk does not"},
        {"ambient_cycle",
         {"amplitude_unit", "period_s", "phase_rad"},
         FitRoute::deterministic,
         "log a board thermistor, or log long enough for 3 cycles: the line at 1/P must be coherent with temperature; "
         "log again at a slightly different sample rate: an aliased mains line moves, a thermal cycle does not"},
        {"gauss_markov",
         {"sigma_unit", "tau_s"},
         FitRoute::spectral,
         "log at least 20 correlation times: one Gauss-Markov gives an ADEV bump less than a decade wide, flicker a "
         "plateau"},
        {"flicker",
         {"b_unit"},
         FitRoute::spectral,
         "log longer (>= 1.5 decades of flat ADEV separate flicker from a single Gauss-Markov process)"},
        {"rate_random_walk",
         {"k_unit_per_sqrt_s"},
         FitRoute::spectral,
         "repeat the run: a random walk differs between runs, a thermal exponential repeats"},
        {"spikes",
         {"rate_hz", "scale_counts"},
         FitRoute::simulated,
         "log the RAW codes too: a spike before the smoother is kernel-shaped, a link error is a single sample"},
        {"adc_dnl",
         {},
         FitRoute::code_density,
         "sweep the input slowly through the codes (a code-density test, IEEE 1241): DNL repeats at the same codes, "
         "whatever the noise or the drift"},
    };
    return list;
}

const std::vector<NotIdentifiable>& not_identifiable_list() {
    static const std::vector<NotIdentifiable> list = {
        {"cross_axis",
         "a static log has constant inputs: misalignment is absorbed in the biases (needs multi-position data)"},
        {"g_sensitivity",
         "gravity is constant on a static table: the gyro's g-sensitivity is absorbed in its bias (needs tilts)"},
        {"bandwidth", "a static input has no frequency content to filter (needs rate steps or turns)"},
        {"scale_factor", "the true rate is zero at rest: a scale-factor error multiplies zero (needs a turntable)"},
        {"temp_scale_factor",
         "the true rate is zero at rest: a scale-factor tempco multiplies zero (needs a turntable)"},
        {"vibration",
         "the table is vibration-isolated: no motion input to identify (needs a shaker or accelerometer reference)"},
        {"saturation", "nothing approaches the rails at rest (needs motion beyond the range)"},
        {"adc_inl",
         "at rest the code follows time, so INL(code) and a slow drift (time) cannot be separated (needs several "
         "offsets)"},
        {"supply_coupling", "no supply channel is logged (log a Vcc divider channel)"},
        {"mains_alias",
         "aliased mains pickup is a sine in the output, the same shape ambient_cycle fits; from one log at one "
         "sample rate the two are one candidate (log at a slightly different rate: an alias moves)"},
        {"clock_jitter",
         "at rest the values hardly change between instants, so a timing error moves them by dy/dt x jitter, "
         "about nothing; the log's own timestamps are summarised under timing (needs a reference clock for the drift)"},
    };
    return list;
}

std::vector<NotIdentifiable> not_tried_without_raw_codes(bool codes_carry_motion) {
    std::vector<NotIdentifiable> out;
    for (const auto& info : candidate_list())
        if (info.route == FitRoute::code_density)
            out.push_back({info.effect, codes_carry_motion
                                            ? "fitted to the raw codes of a raw-mode log, whose codes in motion carry "
                                              "the motion as well as the converter"
                                            : "fitted to codes: a raw-mode log's (a raw_<channel> column) or "
                                              "outputs of one conversion each (window 1), which this log lacks; on "
                                              "smoothed outputs alone the frac cells locate it, weakly"});
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

double candidate_size_in(const sim::EffectSpec& spec, Channel c) {
    const SizeKeys* k = size_keys(spec.name);
    if (!k) return 0.0;
    toml::table t = full_table(spec);
    const toml::value<double>* v = size_value(t, *k, c);
    const double size = v ? v->get() : 0.0;
    // A cycle's size is its coupling times the temperature swing.
    return spec.name == "ambient_cycle" ? size * t["amplitude_k_pp"].value_or(0.0) : size;
}

sim::EffectSpec without_channel(const sim::EffectSpec& spec, Channel c) {
    const SizeKeys* k = size_keys(spec.name);
    if (!k) throw std::invalid_argument("not a mean shape or Gaussian process: " + spec.name);
    sim::EffectSpec out{spec.name, full_table(spec)};
    if (toml::value<double>* v = size_value(out.table, *k, c)) v->get() = 0.0;
    return out;
}

std::vector<double> file_process_params(const sim::EffectSpec& spec, Channel c) {
    const double size = candidate_size_in(spec, c);
    if (spec.name == "gauss_markov") {
        const toml::table t = full_table(spec);
        return {size, t["tau_s"][channel_index(c)].value_or(0.0)};
    }
    if (spec.name == "flicker" || spec.name == "rate_random_walk") return {size};
    throw std::invalid_argument("not a Gaussian process: " + spec.name);
}

void hold_noise(HeldNoise& held, const sim::EffectSpec& spec, Channel c, const GapModel& model) {
    const double cpu = counts_per_unit(model, c);
    const std::vector<double> p = file_process_params(spec, c);
    if (spec.name == "gauss_markov") {
        held.gauss_markov.push_back({std::pow(p[0] * cpu, 2), p[1]});
    } else if (spec.name == "flicker") {
        // The file's own band, which need not be the candidate's.
        const toml::table t = full_table(spec);
        sim::FlickerParams fp;
        fp.f_low_hz = t["f_low_hz"].value_or(fp.f_low_hz);
        fp.f_high_hz = t["f_high_hz"].value_or(fp.f_high_hz);
        const double v = std::pow(p[0] * cpu * sim::Flicker::component_sigma_per_b(), 2);
        const sim::Flicker flicker(fp);
        for (double tau : flicker.component_tau_s()) held.gauss_markov.push_back({v, tau});
    } else {
        held.walk_counts2_per_s += std::pow(p[0] * cpu, 2);
    }
}

sim::EffectSpec make_candidate_effect(const std::string& effect, Channel c, const std::vector<double>& p,
                                      const GapModel& model) {
    sim::EffectSpec spec;
    spec.name = effect;
    toml::table& t = spec.table;
    if (effect == "thermal_second_tc") {
        set_size(t, effect, c, p.at(0));
        t.insert_or_assign("t2_s", per_channel(c, p.at(1), 1800.0));
    } else if (effect == "ambient_cycle") {
        // A sine of 2 K peak to peak with no lag: the coupling is then the amplitude per kelvin.
        t.insert_or_assign("waveform", "sine");
        t.insert_or_assign("amplitude_k_pp", 2.0);
        t.insert_or_assign("period_s", p.at(1));
        t.insert_or_assign("phase_rad", p.at(2));
        t.insert_or_assign("lag_s", 0.0);
        set_size(t, effect, c, p.at(0));
    } else if (effect == "gauss_markov") {
        set_size(t, effect, c, p.at(0));
        t.insert_or_assign("tau_s", per_channel(c, p.at(1), 100.0));
    } else if (effect == "flicker") {
        // The 1/f band spans the log: from below its length to a tenth of the sampling rate (flicker.hpp).
        set_size(t, effect, c, p.at(0));
        const double fs = 1.0 / model.smoothing.sample_period_s;
        t.insert_or_assign("f_high_hz", fs / 10.0);
        t.insert_or_assign("f_low_hz", fs * 1e-5);
    } else if (effect == "rate_random_walk") {
        set_size(t, effect, c, p.at(0));
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
