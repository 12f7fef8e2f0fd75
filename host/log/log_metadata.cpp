// LogMetadata; see log_metadata.hpp.
#include "host/log/log_metadata.hpp"

#include <algorithm>
#include <cmath>

#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/parse_number.hpp"

namespace driftlab::host {

bool LogMetadata::is_valid_key(const std::string& key) {
    if (key.empty() || key == "gap" || key == "driftlab_log") return false;
    if (!(key[0] >= 'a' && key[0] <= 'z')) return false;
    return std::all_of(key.begin(), key.end(),
                       [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; });
}

bool LogMetadata::is_valid_value(const std::string& value) { return value.find_first_of("\r\n") == std::string::npos; }

void LogMetadata::set(const std::string& key, const std::string& value) {
    if (!is_valid_key(key)) throw UsageError("log metadata key '" + key + "' is not lower_snake_case or is reserved");
    if (!is_valid_value(value)) throw UsageError("log metadata value of '" + key + "' contains a line break");
    for (auto& [k, v] : entries_) {
        if (k == key) {
            v = value;
            return;
        }
    }
    entries_.emplace_back(key, value);
}

void LogMetadata::set(const std::string& key, double value) { set(key, format_double(value)); }

void LogMetadata::set(const std::string& key, std::int64_t value) { set(key, std::to_string(value)); }

std::uint64_t LogMetadata::line_of(const std::string& key) const {
    for (const auto& [k, line] : lines_)
        if (k == key) return line;
    return 0;
}

void LogMetadata::set_line(const std::string& key, std::uint64_t line) { lines_.emplace_back(key, line); }

bool LogMetadata::has(const std::string& key) const { return get(key).has_value(); }

std::optional<std::string> LogMetadata::get(const std::string& key) const {
    for (const auto& [k, v] : entries_)
        if (k == key) return v;
    return std::nullopt;
}

std::optional<double> LogMetadata::get_double(const std::string& key) const {
    const auto text = get(key);
    if (!text) return std::nullopt;
    const ParsedNumber p = parse_finite_double(*text);
    if (p.error != NumberError::ok) return std::nullopt;
    return p.value;
}

std::optional<std::int64_t> LogMetadata::get_int(const std::string& key) const {
    const auto value = get_double(key);
    if (!value || *value != std::trunc(*value) || std::fabs(*value) > 9.0e15) return std::nullopt;
    return static_cast<std::int64_t>(*value);
}

}  // namespace driftlab::host
