// Model-file reader; see model_file.hpp and docs/sim.md §Model file.
#include "sim/model/model_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>

#include "driftlab/proto/status.hpp"
#include "firmware/core/config.hpp"
#include "sim/effects/effect.hpp"
#include "sim/effects/params.hpp"
#include "sim/model/paper_model_text.hpp"
#include "sim/model/white_noise.hpp"
#include "sim/sim_error.hpp"

namespace driftlab::sim {

namespace {

enum class Range { any, nonneg, positive, unit_interval };

std::uint32_t line_of(const toml::node& n) { return static_cast<std::uint32_t>(n.source().begin.line); }

// Reads the keys of one table, remembering which were asked for so finish() can reject the rest.
class TableReader {
public:
    TableReader(const toml::table& table, std::string path) : table_(table), path_(std::move(path)) {}

    void number(std::string_view key, double& value, Range range) {
        const toml::node* n = find(key);
        if (n == nullptr) return;
        const auto v = n->value<double>();  // toml++ converts integers too
        if (!v || !n->is_number()) fail(key, *n, "expected a number");
        if (!std::isfinite(*v)) fail(key, *n, "expected a finite number");
        if (const std::string why = beyond_model_magnitude(*v); !why.empty()) fail(key, *n, why);
        switch (range) {
        case Range::any: break;
        case Range::nonneg:
            if (*v < 0.0) fail(key, *n, "must be >= 0, got " + std::to_string(*v));
            break;
        case Range::positive:
            if (!(*v > 0.0)) fail(key, *n, "must be > 0, got " + std::to_string(*v));
            break;
        case Range::unit_interval:
            if (*v < 0.0 || *v > 1.0) fail(key, *n, "must be a probability in [0, 1], got " + std::to_string(*v));
            break;
        }
        value = *v;
    }

    template <class Int>
    void integer(std::string_view key, Int& value, std::int64_t lo, std::int64_t hi) {
        const toml::node* n = find(key);
        if (n == nullptr) return;
        const auto v = n->value_exact<std::int64_t>();
        if (!v) fail(key, *n, "expected an integer");
        if (*v < lo || *v > hi)
            fail(key, *n,
                 "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + std::to_string(*v));
        value = static_cast<Int>(*v);
    }

    void boolean(std::string_view key, bool& value) {
        const toml::node* n = find(key);
        if (n == nullptr) return;
        const auto v = n->value_exact<bool>();
        if (!v) fail(key, *n, "expected true or false");
        value = *v;
    }

    /// A string that must be one of `choices`; returns its index, or -1 when the key is absent.
    int choice(std::string_view key, std::initializer_list<std::string_view> choices) {
        const toml::node* n = find(key);
        if (n == nullptr) return -1;
        const auto v = n->value_exact<std::string>();
        std::string list;
        int index = 0;
        for (auto c : choices) {
            if (v && *v == c) return index;
            list += (list.empty() ? "\"" : ", \"") + std::string(c) + "\"";
            ++index;
        }
        fail(key, *n, "expected one of " + list);
    }

    void string(std::string_view key, std::string& value) {
        const toml::node* n = find(key);
        if (n == nullptr) return;
        const auto v = n->value_exact<std::string>();
        if (!v) fail(key, *n, "expected a string");
        value = *v;
    }

    /// A sub-table, or nullptr when absent.
    const toml::table* table(std::string_view key) {
        const toml::node* n = find(key);
        if (n == nullptr) return nullptr;
        if (!n->is_table()) fail(key, *n, "expected a table");
        return n->as_table();
    }

    /// Rejects every key nobody asked for.
    void finish() const {
        for (const auto& [k, n] : table_)
            if (!seen_.contains(std::string(k.str())))
                throw ConfigError(full(k.str()), line_of(n), "unknown key" + hint());
    }

    [[noreturn]] void fail(std::string_view key, const toml::node& n, const std::string& what) const {
        throw ConfigError(full(key), line_of(n), what);
    }

    std::string full(std::string_view key) const {
        return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
    }

    /// The line of `key` in this table, or the table's own where the file does not set the key.
    std::uint32_t line(std::string_view key) const {
        const toml::node* n = table_.get(key);
        return line_of(n ? *n : static_cast<const toml::node&>(table_));
    }

private:
    const toml::node* find(std::string_view key) {
        seen_.insert(std::string(key));
        return table_.get(key);
    }
    std::string hint() const {
        std::string known;
        for (const auto& k : seen_) known += (known.empty() ? "" : ", ") + k;
        return known.empty() ? std::string(" (this table takes no keys)") : " (expected one of: " + known + ")";
    }

    const toml::table& table_;
    std::string path_;
    std::set<std::string, std::less<>> seen_;
};

void read_adc(TableReader& r, AdcParams& adc) {
    // The firmware's windows, the DNL, INL and bit-flip effects and the converter range checks are all 10-bit
    // (ATmega328P): another resolution would abort the run or stick a channel at the top code.
    r.integer("bits", adc.bits, 10, 10);
    r.number("vref_v", adc.vref_v, Range::positive);
    r.finish();
}

void read_channel(TableReader& r, Channel c, ChannelModel& ch) {
    const std::string u = channel_unit(c);
    FrontEndParams& fe = ch.front_end;
    r.number("sensitivity_v_per_" + u, fe.sensitivity_v_per_unit, Range::positive);
    r.number("null_v", fe.null_v, Range::any);
    r.number("span_" + u, fe.span_unit, Range::positive);
    r.number("center_" + u, fe.center_unit, Range::any);
    r.number("input_" + u, ch.input_unit, Range::any);
    r.number("raw_noise_std_" + u, ch.raw_noise_std_unit, Range::nonneg);
    r.number("drift_c1_counts", ch.drift.c1_counts, Range::any);
    r.number("drift_c2_counts", ch.drift.c2_counts, Range::any);
    r.number("drift_tau_s", ch.drift.tau_s, Range::positive);
    r.finish();
}

// Where a check of a channel's chain, which joins [adc] and the channel's table, points: at `key` in the channel's
// table when the file sets it, else at the channel's table, else at [adc]; 0 when the file sets none of them.
std::uint32_t channel_check_line(const toml::table& root, const std::string& table, const std::string& key = {}) {
    const toml::node* here = key.empty() ? nullptr : root.at_path(table + "." + key).node();
    if (here == nullptr) here = root.at_path(table).node();
    if (here == nullptr) here = root.get("adc");
    return here ? line_of(*here) : 0;
}

// The raw noise in counts depends on [adc] and the channel's front end, either of which the file may set: checked
// for every channel once both are read, at the noise key's line, else the channel table's, else the [adc] table's.
void check_raw_noise(const toml::table& root, const SimModel& m) {
    for (std::size_t i = 0; i < kChannelCount; ++i) {
        const ChannelModel& ch = m.channels[i];
        const std::string key = std::string("raw_noise_std_") + channel_unit(static_cast<Channel>(i));
        const double raw_counts =
            ch.raw_noise_std_unit * FrontEnd(ch.front_end, m.adc.vref_v).counts_per_unit(std::ldexp(1.0, m.adc.bits));
        if (!(raw_counts > 0.0 && raw_counts < kMinCalibratedRawStdCounts)) continue;
        const std::string table = std::string("channels.") + kChannelNames[i];
        throw ConfigError(table + "." + key, channel_check_line(root, table, key),
                          "is " + std::to_string(raw_counts) +
                              " counts; the calibration through the quantiser needs 0 or >= " +
                              std::to_string(kMinCalibratedRawStdCounts) + " counts");
    }
}

// Each number is finite alone, but a channel's front end multiplies and divides them: a span of 1e-308 makes the
// amplifier's gain overflow, and the converter was handed inf times a zero offset, NaN, at the first conversion.
// Checked, as the raw noise, once [adc] and the channel are read, at the channel table's line (else [adc]'s).
void check_front_ends(const toml::table& root, const SimModel& m) {
    for (std::size_t i = 0; i < kChannelCount; ++i) {
        const ChannelModel& ch = m.channels[i];
        const FrontEnd fe(ch.front_end, m.adc.vref_v);
        const double at_rest_v = fe.amplifier_v(fe.sensor_v(ch.input_unit));
        const double counts_per_unit = fe.counts_per_unit(std::ldexp(1.0, m.adc.bits));
        if (std::isfinite(fe.gain()) && fe.gain() > 0.0 && std::isfinite(at_rest_v) && std::isfinite(counts_per_unit))
            continue;
        const std::string table = std::string("channels.") + kChannelNames[i];
        const std::string u = channel_unit(static_cast<Channel>(i));
        char text[320];
        std::snprintf(
            text, sizeof text,
            "its front end leaves the range of a double: amplifier gain vref_v / 2 / (sensitivity_v_per_%s x "
            "span_%s) = %g V/V, converter input at input_%s = %g V, %g counts per %s; each must be finite and "
            "the gain above 0",
            u.c_str(), u.c_str(), fe.gain(), u.c_str(),
            std::isnan(at_rest_v) ? std::numeric_limits<double>::quiet_NaN() : at_rest_v,  // not "-nan" (inf x 0)
            counts_per_unit, u.c_str());
        throw ConfigError(table, channel_check_line(root, table), text);
    }
}

// Where a FirmwareAdjust runs (hil), the firmware fields checked are not the file's alone: whose figures they are.
constexpr const char* kAdjustedConfig =
    "on the configuration that would run: the file's firmware fields with any the preset or the command line sets "
    "over them";

void read_firmware(TableReader& r, proto::ConfigPayload& fw, const FirmwareAdjust& adjust) {
    r.integer("output_period_ms", fw.output_period_ms, proto::kOutputPeriodMinMs, proto::kOutputPeriodMaxMs);
    r.integer("conversions_per_output", fw.conversions_per_output, 1, proto::kConversionsPerOutputMax);
    r.integer("window", fw.window, 1, proto::kWindowMax);
    r.integer("fit_order", fw.fit_order, 0, proto::kFitOrderMax);
    const int mode = r.choice("mode", {"poll", "stream"});
    if (mode >= 0) fw.mode = static_cast<std::uint8_t>(mode);
    bool raw = fw.raw != 0;
    r.boolean("raw", raw);
    fw.raw = raw ? 1 : 0;
    r.finish();
    if (adjust.change) adjust.change(fw);
    // The firmware's own check too, whose limits join fields (a conversion rate too fast for the output period):
    // refused here, not by the board after the handshake; on the configuration that will run (the command line's
    // options over the file's).
    if (const auto refusal = adjust.check ? firmware_refusal(fw) : std::nullopt) {
        throw ConfigError(r.full(refusal->field), r.line(refusal->field),
                          refusal->reason + (adjust.change ? std::string(" (") + kAdjustedConfig + ")" : ""));
    }
}

void read_packet_loss(TableReader& r, PacketLossParams& pl) {
    const int unit = r.choice("unit", {"frame", "byte"});
    if (unit >= 0) pl.unit = unit == 0 ? LossUnit::frame : LossUnit::byte;
    r.number("p_good_to_bad", pl.p_good_to_bad, Range::unit_interval);
    r.number("p_bad_to_good", pl.p_bad_to_good, Range::unit_interval);
    r.number("loss_in_good", pl.loss_in_good, Range::unit_interval);
    r.number("loss_in_bad", pl.loss_in_bad, Range::unit_interval);
    r.finish();
    if (pl.p_good_to_bad > 0.0 && pl.p_bad_to_good == 0.0)
        throw ConfigError(r.full("p_bad_to_good"), r.line("p_bad_to_good"),
                          "must be > 0 when p_good_to_bad > 0 (the link would never recover)");
}

void read_direction(TableReader& r, DirectionParams& d) {
    r.number("latency_s", d.latency_s, Range::nonneg);
    r.number("byte_error_rate", d.byte_error_rate, Range::unit_interval);
    r.number("byte_drop_rate", d.byte_drop_rate, Range::unit_interval);
    if (const toml::table* t = r.table("packet_loss")) {
        TableReader sub(*t, r.full("packet_loss"));
        read_packet_loss(sub, d.packet_loss);
    }
    r.finish();
}

void read_link(TableReader& r, LinkParams& link) {
    r.number("baud", link.baud, Range::positive);
    if (const toml::table* t = r.table("to_host")) {
        TableReader sub(*t, r.full("to_host"));
        read_direction(sub, link.to_host);
    }
    if (const toml::table* t = r.table("to_firmware")) {
        TableReader sub(*t, r.full("to_firmware"));
        read_direction(sub, link.to_firmware);
    }
    r.finish();
}

// An effect is a table, or an array of tables for several instances (one per channel, say); each is validated now,
// so a bad effect fails at load time.
void read_effects(const toml::table& effects, std::vector<EffectSpec>& out) {
    for (const auto& [k, n] : effects) {
        const std::string name(k.str());
        const std::string path = "effects." + name;
        if (const toml::array* instances = n.as_array(); instances && instances->is_array_of_tables()) {
            for (std::size_t j = 0; j < instances->size(); ++j) {
                const toml::table& t = *instances->get(j)->as_table();
                make_effect(name, t, path + "[" + std::to_string(j) + "]");
                out.push_back({name, t});
            }
            continue;
        }
        if (!n.is_table())
            throw ConfigError(path, line_of(n), "expected a table of the effect's parameters (or an array of them)");
        make_effect(name, *n.as_table(), path);
        out.push_back({name, *n.as_table()});
    }
}

// The file's tables of effect `name` (one, or one per instance): they keep their source lines, which the copies in
// SimModel::effects lose.
std::vector<const toml::table*> effect_tables(const toml::table& root, std::string_view name) {
    std::vector<const toml::table*> out;
    const toml::node_view<const toml::node> n = root["effects"][name];
    if (const toml::table* t = n.as_table()) out.push_back(t);
    if (const toml::array* a = n.as_array())
        for (const toml::node& i : *a)
            if (const toml::table* t = i.as_table()) out.push_back(t);
    return out;
}

// Clock jitter comparable to a channel's conversion interval would reorder its conversions (sim/effects/
// clock_jitter.hpp); only with the firmware's final CONFIG is that interval known, so it is checked here.
void check_clock_jitter(const toml::table& root, const proto::ConfigPayload& fw, bool adjusted) {
    const double interval_s = fw.output_period_ms / 1000.0 / fw.conversions_per_output;
    for (const toml::table* e : effect_tables(root, "clock_jitter")) {
        const double rate = 1.0 + (*e)["drift_ppm"].value<double>().value_or(0.0) * 1e-6;
        const double jitter_s = (*e)["jitter_s"].value<double>().value_or(0.0);
        // A tenth: two neighbours' instants then swap with probability Phi(-10/sqrt(2)) < 1e-12.
        const double limit_s = 0.1 * interval_s * rate;
        if (jitter_s <= limit_s) continue;
        char text[512];
        std::snprintf(text, sizeof text,
                      "%g s is not well below a channel's conversion interval (%g s: output_period_ms %u / "
                      "conversions_per_output %u%s%s); at most %g s (a tenth), or conversions would be reordered",
                      jitter_s, interval_s * rate, static_cast<unsigned>(fw.output_period_ms),
                      static_cast<unsigned>(fw.conversions_per_output), adjusted ? ", " : "",
                      adjusted ? kAdjustedConfig : "", limit_s);
        throw ConfigError("effects.clock_jitter.jitter_s", line_of(*e->get("jitter_s")), text);
    }
}

// temp_scale_factor needs the chain's temperature, which only ambient_cycle models (sensor_model.cpp): without it
// the effect would silently do nothing.
void check_temperature_source(const toml::table& root, const SimModel& m) {
    const auto has = [&m](std::string_view name) {
        return std::any_of(m.effects.begin(), m.effects.end(), [name](const EffectSpec& e) { return e.name == name; });
    };
    if (!has("temp_scale_factor") || has("ambient_cycle")) return;
    const auto tables = effect_tables(root, "temp_scale_factor");
    throw ConfigError("effects.temp_scale_factor", tables.empty() ? 0 : line_of(*tables.front()),
                      "needs the unit's temperature, which only [effects.ambient_cycle] models (its 25 degC mean plus "
                      "the lagged swing); without it the effect would do nothing");
}

SimModel read_model(const toml::table& root, SimModel m, const FirmwareAdjust& adjust) {
    TableReader r(root, "");
    r.string("name", m.name);
    if (const toml::table* t = r.table("adc")) {
        TableReader sub(*t, "adc");
        read_adc(sub, m.adc);
    }
    if (const toml::table* t = r.table("channels")) {
        TableReader chans(*t, "channels");
        for (std::size_t i = 0; i < kChannelCount; ++i) {
            if (const toml::table* ct = chans.table(kChannelNames[i])) {
                TableReader sub(*ct, chans.full(kChannelNames[i]));
                read_channel(sub, static_cast<Channel>(i), m.channels[i]);
            }
        }
        chans.finish();
    }
    check_front_ends(root, m);
    check_raw_noise(root, m);
    if (const toml::table* t = r.table("effects")) read_effects(*t, m.effects);
    check_temperature_source(root, m);
    if (const toml::table* t = r.table("firmware")) {
        TableReader sub(*t, "firmware");
        read_firmware(sub, m.firmware, adjust);
    } else if (adjust.change) {
        adjust.change(m.firmware);
    }
    check_clock_jitter(root, m.firmware, static_cast<bool>(adjust.change));
    if (const toml::table* t = r.table("link")) {
        TableReader sub(*t, "link");
        read_link(sub, m.link);
    }
    r.finish();
    return m;
}

// Every field gets a value here; the built-in paper.toml then sets the paper's unit over it.
SimModel empty_model() {
    SimModel m;
    m.firmware = {1000, 1, 1, 0, 0, 0};
    return m;
}

SimModel parse_over(std::string_view text, const std::string& source_name, const SimModel& base,
                    const FirmwareAdjust& adjust = {}) {
    toml::table root;
    try {
        root = toml::parse(text, source_name);
    } catch (const toml::parse_error& e) {
        throw ModelFileError(source_name + ":" + std::to_string(e.source().begin.line), "syntax",
                             std::string(e.description()));
    }
    try {
        return read_model(root, base, adjust);
    } catch (const ConfigError& e) {
        // e.what() is "line N: key: reason"; the host error puts file:line and key in front itself.
        const std::string where = e.line() > 0 ? source_name + ":" + std::to_string(e.line()) : source_name;
        const std::string prefix =
            (e.line() > 0 ? "line " + std::to_string(e.line()) + ": " : std::string()) + e.key() + ": ";
        std::string reason = e.what();
        if (reason.starts_with(prefix)) reason.erase(0, prefix.size());
        throw ModelFileError(where, e.key(), reason);
    }
}

}  // namespace

std::string_view paper_model_text() { return kPaperModelToml; }

SimModel paper_model() {
    static const SimModel m = parse_over(kPaperModelToml, "paper.toml (built in)", empty_model());
    return m;
}

SimModel parse_model(std::string_view toml_text, const std::string& source_name, const FirmwareAdjust& adjust) {
    return parse_over(toml_text, source_name, paper_model(), adjust);
}

SimModel load_model_file(const std::string& path, const FirmwareAdjust& adjust) {
    // A stream opens a folder and reads it as empty, which had run the paper's model under the folder's name.
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw ModelFileError(path, "file", "is a folder, not a model file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ModelFileError(path, "file", "cannot open the model file (does it exist and is it readable?)");
    // A model file is a few kilobytes; a larger one is refused before it is held (its parse tree takes several times
    // its text).
    std::string text;
    char chunk[1 << 16];
    while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
        text.append(chunk, static_cast<std::size_t>(in.gcount()));
        if (text.size() > kMaxModelFileBytes)
            throw ModelFileError(path, "file", "longer than 1 MiB, the most a model file may hold");
    }
    return parse_model(text, path, adjust);
}

std::optional<FirmwareRefusal> firmware_refusal(const proto::ConfigPayload& fw) {
    const fw::ConfigCheck check = fw::validate(fw);
    if (check.status == proto::Status::ok) return std::nullopt;
    const char* name = proto::config_field_name(check.field);
    const std::string field = name ? name : "conversions_per_output";
    // The firmware names only the field; the reason, with the values it saw, is what lets a user fix it.
    const auto range = [](long lo, long hi, long got) {
        return "must be " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " + std::to_string(got);
    };
    std::string why;
    if (field == "output_period_ms")
        why = range(proto::kOutputPeriodMinMs, proto::kOutputPeriodMaxMs, fw.output_period_ms);
    else if (field == "window")
        why = range(1, std::min<long>(proto::kWindowMax, fw::LsWindow::kMaxWindow), fw.window);
    else if (field == "fit_order")
        why = range(0, proto::kFitOrderMax, fw.fit_order);
    else if (field == "mode")
        why = range(0, 1, fw.mode) + " (0 poll, 1 stream)";
    else if (field == "raw")
        why = range(0, 1, fw.raw);
    else if (fw.conversions_per_output < 1 || fw.conversions_per_output > proto::kConversionsPerOutputMax)
        why = range(1, proto::kConversionsPerOutputMax, fw.conversions_per_output);
    else
        why = "output_period_ms " + std::to_string(fw.output_period_ms) + " / (4 channels x conversions_per_output " +
              std::to_string(fw.conversions_per_output) + ") gives a conversion period of " +
              std::to_string(fw::conversion_period_ticks(fw.output_period_ms, fw.conversions_per_output)) +
              " ticks of 4 us; the firmware needs " + std::to_string(fw::kMinConversionPeriodTicks) + " to " +
              std::to_string(fw::kMaxConversionPeriodTicks) +
              " (0.2 to 262 ms): fewer conversions per output or a longer output period";
    return FirmwareRefusal{field, std::string("the firmware refuses this configuration (") +
                                      proto::status_name(check.status) + "): " + why};
}

}  // namespace driftlab::sim
