// Parameter visitors: one `visit(V&)` per effect parameter struct drives TOML parsing, TOML/JSON output and the
// parameter documentation, so the three cannot disagree (docs/effects.md lists what list_effects() returns).
#pragma once

#include <array>
#include <cstdint>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <toml++/toml.h>

#include "sim/effects/effect.hpp"

namespace driftlab::sim {

/// Range a number must lie in. All but `limit` (a clipping rail, +-inf = none) require a finite value.
enum class Check : std::uint8_t { any, nonneg, positive, unit_interval, limit };

/// The largest magnitude of a model file's finite numbers. Near the largest double, the chain's arithmetic (a size
/// times counts per unit, squared for a variance) overflows mid-run into inf and NaN; no sensor described in these
/// units (V, s, Hz, deg/s, g, counts, ppm) comes near it.
inline constexpr double kMaxModelMagnitude = 1e100;

/// Why `v` may not stand in a model file for its size, or empty: "got V: beyond +-1e100, ...". Infinities are left to
/// the caller's range check.
std::string beyond_model_magnitude(double v);

/// Reads a parameter struct from a TOML table; unknown keys and bad values throw ConfigError naming the key.
class TomlReader {
public:
    TomlReader(const toml::table& table, std::string_view key_path) : table_(table), path_(key_path) {}

    void field(std::string_view key, double& value, std::string_view unit, std::string_view doc,
               Check check = Check::any);
    /// A scalar broadcasts to every element; an array must have exactly N elements.
    template <std::size_t N>
    void field(std::string_view key, std::array<double, N>& value, std::string_view unit, std::string_view,
               Check check = Check::any) {
        read_fixed(key, value.data(), N, unit, check);
    }
    /// Rows of a matrix (array of arrays); no broadcast.
    void field(std::string_view key, std::array<std::array<double, 3>, 3>& value, std::string_view unit,
               std::string_view doc, Check check = Check::any);
    void field(std::string_view key, std::vector<double>& value, std::string_view unit, std::string_view doc,
               Check check = Check::any);
    void field(std::string_view key, std::vector<std::int64_t>& value, std::string_view unit, std::string_view doc,
               std::int64_t min_value, std::int64_t max_value);
    void field(std::string_view key, std::uint64_t& value, std::string_view unit, std::string_view doc);
    void field(std::string_view key, bool& value, std::string_view unit, std::string_view doc);
    /// A string that must be one of `choices`.
    void choice(std::string_view key, std::string& value, const std::vector<std::string_view>& choices,
                std::string_view doc);

    /// Throws on any key of the table that no field() asked for, suggesting same-named keys with another unit.
    void finish() const;
    /// Throws ConfigError for `key` (cross-field checks after the visit).
    [[noreturn]] void fail(std::string_view key, const std::string& what) const;

private:
    const toml::node* find(std::string_view key, std::string_view unit);
    void read_fixed(std::string_view key, double* out, std::size_t n, std::string_view unit, Check check);
    double number(const toml::node& node, std::string_view key, std::string_view unit, Check check) const;
    std::string full_key(std::string_view key) const;

    const toml::table& table_;
    std::string path_;
    std::set<std::string, std::less<>> seen_;
    std::vector<std::pair<std::string, std::string>> known_;  // key, unit: for "did you mean" hints
};

/// Writes a parameter struct into a TOML table under the same keys.
class TomlWriter {
public:
    template <class T>
    void field(std::string_view key, const T& value, std::string_view, std::string_view, Check = Check::any) {
        table_.insert_or_assign(key, to_node(value));
    }
    void field(std::string_view key, const std::vector<std::int64_t>& value, std::string_view, std::string_view,
               std::int64_t, std::int64_t) {
        table_.insert_or_assign(key, to_node(value));
    }
    void choice(std::string_view key, const std::string& value, const std::vector<std::string_view>&,
                std::string_view) {
        table_.insert_or_assign(key, value);
    }
    const toml::table& table() const { return table_; }

    static toml::array to_node(const std::vector<double>& v);
    static toml::array to_node(const std::vector<std::int64_t>& v);
    static toml::array to_node(const std::array<std::array<double, 3>, 3>& m);
    template <std::size_t N>
    static toml::array to_node(const std::array<double, N>& v) {
        toml::array a;
        for (double x : v) a.push_back(x);
        return a;
    }
    static double to_node(double v) { return v; }
    static bool to_node(bool v) { return v; }
    static std::int64_t to_node(std::uint64_t v) { return static_cast<std::int64_t>(v); }

private:
    toml::table table_;
};

/// The shortest TOML text that reads back as `v` exactly, always a float (model files, `driftlab effects`).
std::string toml_number_text(double v);

/// A parameter's value as TOML text: a number as toml_number_text() writes it, a flag, a string or an array of
/// them (effect tables are flat). Throws std::invalid_argument on a table.
std::string toml_value_text(const toml::node& n);

/// Collects ParamInfo (key, unit, default as TOML text, doc) from a default-constructed struct.
class ParamDescriber {
public:
    template <class T>
    void field(std::string_view key, const T& value, std::string_view unit, std::string_view doc, Check = Check::any) {
        add(key, unit, text_of(TomlWriter::to_node(value)), doc);
    }
    void field(std::string_view key, const std::vector<std::int64_t>& value, std::string_view unit,
               std::string_view doc, std::int64_t, std::int64_t) {
        add(key, unit, text_of(TomlWriter::to_node(value)), doc);
    }
    void choice(std::string_view key, const std::string& value, const std::vector<std::string_view>& choices,
                std::string_view doc);
    std::vector<ParamInfo> take() { return std::move(params_); }

private:
    template <class N>
    static std::string text_of(const N& node) {
        if constexpr (std::is_base_of_v<toml::node, N>) {
            return toml_value_text(node);
        } else {
            return toml_value_text(toml::value<N>(node));
        }
    }
    void add(std::string_view key, std::string_view unit, std::string text, std::string_view doc);
    std::vector<ParamInfo> params_;
};

/// Parameters of a default-constructed `Params`, documented.
template <class Params>
std::vector<ParamInfo> describe_params() {
    Params p;
    ParamDescriber d;
    p.visit(d);
    return d.take();
}

/// Parameters as a TOML table.
template <class Params>
toml::table params_to_toml(const Params& params) {
    Params copy = params;
    TomlWriter w;
    copy.visit(w);
    return w.table();
}

/// Parameters read from a TOML table; calls `Params::validate(TomlReader&)` for cross-field checks if it exists.
template <class Params>
Params params_from_toml(const toml::table& table, std::string_view key_path) {
    Params p;
    TomlReader r(table, key_path);
    p.visit(r);
    r.finish();
    if constexpr (requires(const Params& q, const TomlReader& rr) { q.validate(rr); }) p.validate(r);
    return p;
}

/// Base for effects with a parameter struct: stores it, exposes it, writes it back to TOML; names the effect and its
/// stage from the derived class's kName and kStage (an effect whose stage is a parameter overrides stage()).
template <class Derived, class Params>
class EffectWith : public Effect {
public:
    explicit EffectWith(const Params& params) : p_(params) {}
    std::string_view name() const override { return Derived::kName; }
    Stage stage() const override { return Derived::kStage; }
    const Params& params() const { return p_; }
    toml::table parameters() const override { return params_to_toml(p_); }

protected:
    Params p_;
};

/// gyro field [deg/s] and accel fields [g] as one per-channel array in the physical stage's units.
inline ChannelValues physical_per_channel(double gyro_dps, const std::array<double, 3>& accel_g) {
    return {gyro_dps, accel_g[0], accel_g[1], accel_g[2]};
}

/// Indices [first, last) of the channels an instant covers (one conversion or all four).
struct ChannelSpan {
    std::size_t first;
    std::size_t last;
};
inline ChannelSpan channels_of(const EffectContext& ctx) {
    if (ctx.channel) {
        const std::size_t c = channel_index(*ctx.channel);
        return {c, c + 1};
    }
    return {0, kChannelCount};
}

}  // namespace driftlab::sim
