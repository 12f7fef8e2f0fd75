// Parameter visitors: TOML reading with key/unit-naming errors, writing, documentation (params.hpp).
#include "sim/effects/params.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace driftlab::sim {
namespace {

std::string check_text(Check check) {
    switch (check) {
    case Check::nonneg: return " >= 0";
    case Check::positive: return " > 0";
    case Check::unit_interval: return " in [0, 1]";
    case Check::limit: return " (inf allowed)";
    case Check::any: break;
    }
    return "";
}

bool passes(double v, Check check) {
    if (std::isnan(v)) return false;
    if (check == Check::limit) return true;
    if (!std::isfinite(v)) return false;
    switch (check) {
    case Check::nonneg: return v >= 0.0;
    case Check::positive: return v > 0.0;
    case Check::unit_interval: return v >= 0.0 && v <= 1.0;
    case Check::limit:
    case Check::any: break;
    }
    return true;
}

std::uint32_t line_of(const toml::node& node) { return node.source().begin.line; }

std::string first_token(std::string_view key) { return std::string(key.substr(0, key.find('_'))); }

}  // namespace

std::string beyond_model_magnitude(double v) {
    if (!std::isfinite(v) || std::fabs(v) <= kMaxModelMagnitude) return "";
    std::ostringstream os;
    os << "got " << v << ": beyond +-" << kMaxModelMagnitude
       << ", where the simulation's arithmetic overflows (a size times counts per unit, squared for a variance)";
    return os.str();
}

std::string TomlReader::full_key(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void TomlReader::fail(std::string_view key, const std::string& what) const {
    const toml::node* node = table_.get(key);
    throw ConfigError(full_key(key), node != nullptr ? line_of(*node) : line_of(table_), what);
}

const toml::node* TomlReader::find(std::string_view key, std::string_view unit) {
    seen_.emplace(key);
    known_.emplace_back(std::string(key), std::string(unit));
    return table_.get(key);
}

double TomlReader::number(const toml::node& node, std::string_view key, std::string_view unit, Check check) const {
    const std::optional<double> v = node.value<double>();  // integers convert too
    const std::string expected = "expected a number [" + std::string(unit) + "]" + check_text(check);
    if (!v || !(node.is_floating_point() || node.is_integer())) {
        std::ostringstream os;
        os << expected << ", got " << node.type();
        throw ConfigError(full_key(key), line_of(node), os.str());
    }
    if (!passes(*v, check)) {
        std::ostringstream os;
        os << expected << ", got " << *v;
        throw ConfigError(full_key(key), line_of(node), os.str());
    }
    if (const std::string why = beyond_model_magnitude(*v); !why.empty())
        throw ConfigError(full_key(key), line_of(node), why);
    return *v;
}

void TomlReader::field(std::string_view key, double& value, std::string_view unit, std::string_view, Check check) {
    if (const toml::node* node = find(key, unit)) value = number(*node, key, unit, check);
}

void TomlReader::read_fixed(std::string_view key, double* out, std::size_t n, std::string_view unit, Check check) {
    const toml::node* node = find(key, unit);
    if (node == nullptr) return;
    if (const toml::array* a = node->as_array()) {
        if (a->size() != n) {
            throw ConfigError(full_key(key), line_of(*node),
                              "expected a number or an array of " + std::to_string(n) + " numbers [" +
                                  std::string(unit) + "], got " + std::to_string(a->size()) + " elements");
        }
        for (std::size_t i = 0; i < n; ++i) out[i] = number((*a)[i], key, unit, check);
        return;
    }
    const double v = number(*node, key, unit, check);
    for (std::size_t i = 0; i < n; ++i) out[i] = v;
}

void TomlReader::field(std::string_view key, std::array<std::array<double, 3>, 3>& value, std::string_view unit,
                       std::string_view, Check check) {
    const toml::node* node = find(key, unit);
    if (node == nullptr) return;
    const toml::array* rows = node->as_array();
    const std::string expected = "expected a 3x3 matrix (3 arrays of 3 numbers) [" + std::string(unit) + "]";
    if (rows == nullptr || rows->size() != 3) throw ConfigError(full_key(key), line_of(*node), expected);
    for (std::size_t i = 0; i < 3; ++i) {
        const toml::array* row = (*rows)[i].as_array();
        if (row == nullptr || row->size() != 3) throw ConfigError(full_key(key), line_of((*rows)[i]), expected);
        for (std::size_t j = 0; j < 3; ++j) value[i][j] = number((*row)[j], key, unit, check);
    }
}

void TomlReader::field(std::string_view key, std::vector<double>& value, std::string_view unit, std::string_view,
                       Check check) {
    const toml::node* node = find(key, unit);
    if (node == nullptr) return;
    const toml::array* a = node->as_array();
    if (a == nullptr) {
        throw ConfigError(full_key(key), line_of(*node), "expected an array of numbers [" + std::string(unit) + "]");
    }
    value.clear();
    for (const toml::node& e : *a) value.push_back(number(e, key, unit, check));
}

void TomlReader::field(std::string_view key, std::vector<std::int64_t>& value, std::string_view unit, std::string_view,
                       std::int64_t min_value, std::int64_t max_value) {
    const toml::node* node = find(key, unit);
    if (node == nullptr) return;
    const std::string expected = "expected an array of integers [" + std::string(unit) + "] in [" +
                                 std::to_string(min_value) + ", " + std::to_string(max_value) + "]";
    const toml::array* a = node->as_array();
    if (a == nullptr) throw ConfigError(full_key(key), line_of(*node), expected);
    value.clear();
    for (const toml::node& e : *a) {
        const std::optional<std::int64_t> v = e.is_integer() ? e.value<std::int64_t>() : std::nullopt;
        if (!v || *v < min_value || *v > max_value) throw ConfigError(full_key(key), line_of(e), expected);
        value.push_back(*v);
    }
}

void TomlReader::field(std::string_view key, std::uint64_t& value, std::string_view unit, std::string_view) {
    const toml::node* node = find(key, unit);
    if (node == nullptr) return;
    const std::optional<std::int64_t> v = node->is_integer() ? node->value<std::int64_t>() : std::nullopt;
    if (!v || *v < 0) throw ConfigError(full_key(key), line_of(*node), "expected a non-negative integer");
    value = static_cast<std::uint64_t>(*v);
}

void TomlReader::field(std::string_view key, bool& value, std::string_view unit, std::string_view) {
    const toml::node* node = find(key, unit);
    if (node == nullptr) return;
    if (!node->is_boolean()) throw ConfigError(full_key(key), line_of(*node), "expected true or false");
    value = *node->value<bool>();
}

void TomlReader::choice(std::string_view key, std::string& value, const std::vector<std::string_view>& choices,
                        std::string_view) {
    const toml::node* node = find(key, "");
    if (node == nullptr) return;
    std::string list;
    for (std::string_view c : choices) list += (list.empty() ? "\"" : ", \"") + std::string(c) + "\"";
    const std::optional<std::string> v = node->value<std::string>();
    if (!node->is_string() || !v) throw ConfigError(full_key(key), line_of(*node), "expected one of " + list);
    for (std::string_view c : choices) {
        if (*v == c) {
            value = *v;
            return;
        }
    }
    throw ConfigError(full_key(key), line_of(*node), "expected one of " + list + ", got \"" + *v + "\"");
}

void TomlReader::finish() const {
    for (const auto& [k, node] : table_) {
        if (seen_.count(k.str()) != 0) continue;
        std::string hint;
        for (const auto& [known, unit] : known_) {
            if (first_token(known) != first_token(k.str())) continue;
            hint += (hint.empty() ? "" : ", ") + known + (unit.empty() ? "" : " [" + unit + "]");
        }
        throw ConfigError(full_key(k.str()), line_of(node),
                          hint.empty() ? "unknown key" : "unknown key or unit; expected " + hint);
    }
}

toml::array TomlWriter::to_node(const std::vector<double>& v) {
    toml::array a;
    for (double x : v) a.push_back(x);
    return a;
}

toml::array TomlWriter::to_node(const std::vector<std::int64_t>& v) {
    toml::array a;
    for (std::int64_t x : v) a.push_back(x);
    return a;
}

toml::array TomlWriter::to_node(const std::array<std::array<double, 3>, 3>& m) {
    toml::array rows;
    for (const auto& r : m) rows.push_back(to_node(r));
    return rows;
}

std::string toml_number_text(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[32];
    const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
    std::string text(buf, end);
    if (text.find_first_of(".en") == std::string::npos) text += ".0";
    return text;
}

std::string toml_value_text(const toml::node& n) {
    if (const auto* v = n.as_floating_point()) return toml_number_text(v->get());
    if (const auto* v = n.as_integer()) return std::to_string(v->get());
    if (const auto* v = n.as_boolean()) return v->get() ? "true" : "false";
    std::ostringstream out;
    if (const auto* v = n.as_string()) {
        out << *v;  // toml++ quotes and escapes it
    } else if (const auto* a = n.as_array()) {
        out << "[";
        for (std::size_t k = 0; k < a->size(); ++k) out << (k ? ", " : "") << toml_value_text(*a->get(k));
        out << "]";
    } else {
        throw std::invalid_argument("an effect parameter that is neither a value nor an array");
    }
    return out.str();
}

void ParamDescriber::add(std::string_view key, std::string_view unit, std::string text, std::string_view doc) {
    params_.push_back({std::string(key), std::string(unit), std::move(text), std::string(doc)});
}

void ParamDescriber::choice(std::string_view key, const std::string& value,
                            const std::vector<std::string_view>& choices, std::string_view doc) {
    std::string d(doc);
    d += " (";
    for (std::size_t i = 0; i < choices.size(); ++i) d += (i > 0 ? " | " : "") + std::string(choices[i]);
    d += ")";
    add(key, "", "\"" + value + "\"", d);
}

}  // namespace driftlab::sim
