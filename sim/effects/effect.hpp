// The simulator's effect interface, its context and the registry; spec in docs/effects.md.
//
// How to use (chain side). An effect is one named, parameterised error source (E1..E15 of the gap method, plus
// temp_scale_factor; E16, the link, lives in sim/link) that acts at one stage of the sensor chain:
//   true input [deg/s, g] -> physical effects -> transducer -> analog effects [V] -> ADC input in counts
//   -> converter effects [counts] -> round + clip 0..1023 -> code;   timing effects move the conversion instants.
// Build effects with `make_effect(name, toml_table, key_path)`, call `reset(seed)` once per run, then for every
// instant call `apply_in_chain(effect, values, ctx)` (or `apply`) with all four channels in the stage's unit. Converter
// effects receive the CONTINUOUS ADC input v/LSB (not yet rounded); a converter effect that quantises (adc_dnl) returns
// integral codes, which the chain's final round-and-clip leaves unchanged.
//
// Per-sample vs per-conversion. An instant is either a sample of all four channels (ctx.channel empty: every
// entry of `values` is updated) or one conversion of the round-robin ADC (ctx.channel = c: only values[c] is read
// and written, the other entries are left untouched). Stateful effects keep one state and one RNG substream per
// channel, so a channel sees the same random sequence in both modes given the same instants; ctx.dt_s is the time
// since the previous instant of THAT channel (0 at the first instant after reset).
//
// Order: within a stage apply effects in list_effects() order, `application_rank(name)` (e.g. adc_inl shifts
// transitions before adc_dnl quantises; saturation clips after the biases). Input effects (is_input():
// vibration) are real motion and pure functions of t: they must reach ctx.true_physical for all four channels, so
// cross-couplings (g_sensitivity reads the accel axes while the gyro is converted) see them.
// `apply_in_chain(effect, values, ctx)` does both cases; calling it for every effect is the whole contract.
//
// Timing effects (stage timing) do nothing in apply(); the chain asks `actual_instant_s(nominal_s, ctx)` for each
// conversion (ctx.channel set) or sample, then evaluates the other effects at the returned instant.
//
// Units: every parameter field carries its unit in its name (`_s`, `_hz`, `_v`, `_dps`, `_g`, `_lsb`, `_pct`...).
// Physical-stage parameters come as a gyro field in deg/s and an accel field in g (x, y, z). Every effect is off
// by default: default parameters make apply() the identity and actual_instant_s() return its argument.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "driftlab/channels.hpp"

namespace driftlab::sim {

/// Where in the chain an effect acts, and therefore the unit of the values it sees.
enum class Stage : std::uint8_t {
    physical,   ///< true input plus errors, [deg/s] for gyro, [g] for accel_x..z
    analog,     ///< sensor/amplifier output at the ADC pin [V]
    converter,  ///< ADC input/output [counts] (continuous before the final round-and-clip)
    timing,     ///< conversion instants [s]
};

/// "physical", "analog", "converter", "timing": the names used in TOML, JSON and docs.
const char* stage_name(Stage stage);

/// One instant of all four channels, indexed by channel_index(Channel), in the stage's unit.
using ChannelValues = std::array<double, kChannelCount>;

/// A quantity the chain does not model (temperature, supply) is NaN; effects needing it then act as identity.
inline constexpr double kNotModelled = std::numeric_limits<double>::quiet_NaN();

/// What the chain knows about the instant being processed.
struct EffectContext {
    double t_s = 0.0;   ///< actual instant since power-on [s] (after timing effects)
    double dt_s = 0.0;  ///< since the previous instant of this channel/sample [s]; 0 at first
    /// At a channel's first instant, the time since the sensor's power-on that nobody converted [s]; 0 otherwise
    /// and when the caller does not know it. A process that runs from power-on (rate_random_walk) steps across
    /// it; the others start at the first instant (a spike would get a spurious chance there).
    double since_power_on_s = 0.0;
    std::optional<Channel> channel;          ///< set: one conversion of this channel; empty: all four channels
    double temperature_degc = kNotModelled;  ///< ambient/internal temperature if the chain models it [degC]
    double supply_v = kNotModelled;          ///< supply voltage if the chain models it [V]
    ChannelValues true_physical{};           ///< true inputs: gyro [deg/s], accel_x..z [g] (for cross-couplings)
};

/// Bad model-file content: names the TOML key path (and line when known) and what was expected, with its unit.
/// sim code throws this; the host's model-file loader turns it into its own ConfigError with the file name.
class ConfigError : public std::runtime_error {
public:
    ConfigError(std::string key, std::uint32_t line, const std::string& what)
        : std::runtime_error(format(key, line, what)), key_(std::move(key)), line_(line) {}
    /// Dotted key path, e.g. "effects.gauss_markov.tau_s".
    const std::string& key() const { return key_; }
    /// 1-based line in the TOML source, 0 when unknown.
    std::uint32_t line() const { return line_; }

private:
    static std::string format(const std::string& key, std::uint32_t line, const std::string& what) {
        return (line > 0 ? "line " + std::to_string(line) + ": " : std::string()) + key + ": " + what;
    }
    std::string key_;
    std::uint32_t line_;
};

/// One error source. Implementations live in sim/effects/<name>.hpp/.cpp, one per name.
class Effect {
public:
    virtual ~Effect() = default;
    /// Exactly the config/output name (e.g. "gauss_markov").
    virtual std::string_view name() const = 0;
    /// The stage it acts at (fixed per effect, except saturation/spikes whose `stage` key chooses).
    virtual Stage stage() const = 0;
    /// Restart the effect for a run: clear state, re-seed its own substreams from `seed` (effect_stream_id).
    virtual void reset(std::uint64_t seed) = 0;
    /// Act on one instant in the stage's unit (see the file comment for per-sample vs per-conversion).
    virtual void apply(ChannelValues& values, const EffectContext& ctx) = 0;
    /// Timing effects: map a nominal conversion/sample instant to the actual one [s]. Others: identity.
    virtual double actual_instant_s(double nominal_s, const EffectContext& ctx);
    /// True for effects that are a real input (vibration): the chain adds them to ctx.true_physical as well, so
    /// cross-couplings (cross_axis, g_sensitivity, temp_scale_factor) see them (file comment, "Order").
    virtual bool is_input() const { return false; }
    /// The unit's temperature at t [degC] for an effect that models it (ambient_cycle): the chain passes the first
    /// such effect's to all as ctx.temperature_degc. kNotModelled, at every t, for the others.
    virtual double temperature_degc(double /*t_s*/) const { return kNotModelled; }
    /// Current parameters under their TOML keys (round trip and JSON output).
    virtual toml::table parameters() const = 0;
};

/// Documentation of one parameter, for docs/effects.md and `list_effects()` JSON.
struct ParamInfo {
    std::string key;           ///< TOML key, unit-suffixed
    std::string unit;          ///< e.g. "deg/s", "s", "V", "LSB", "%"
    std::string default_text;  ///< default as TOML text
    std::string doc;           ///< one line
};

/// Documentation of one effect.
struct EffectInfo {
    std::string name;
    Stage stage;
    std::string equation;
    std::string summary;
    std::vector<ParamInfo> params;
};

/// Every effect the registry knows, in the recommended application order.
const std::vector<EffectInfo>& list_effects();

/// Position of `name` in list_effects(): sort a stage's effects by it. Unknown names sort last.
std::size_t application_rank(std::string_view name);

/// Applies one effect as the chain must: an input effect (is_input()) is evaluated for all four channels at
/// ctx.t_s, added to ctx.true_physical and to the channel(s) of this instant; any other effect is apply()'d.
void apply_in_chain(Effect& effect, ChannelValues& values, EffectContext& ctx);

/// True when `name` is an effect name.
bool is_effect_name(std::string_view name);

/// Build an effect from its TOML table. `key_path` prefixes error keys (e.g. "effects.gauss_markov").
/// Throws ConfigError on an unknown name, an unknown key (with the expected unit-suffixed key when only the unit
/// differs), a wrong type or a value out of range.
std::unique_ptr<Effect> make_effect(std::string_view name, const toml::table& table, std::string_view key_path);

/// Build an effect with default parameters (identity).
std::unique_ptr<Effect> make_effect(std::string_view name);

/// RNG substream of one channel of one effect: depends on the name only, so switching another effect on or off
/// never changes this effect's draws. Pass to `Rng(seed, effect_stream_id(name, channel))`.
std::uint64_t effect_stream_id(std::string_view name, std::size_t channel);

}  // namespace driftlab::sim
