// Metadata of a canonical log: the ordered `# key: value` lines after `# driftlab-log: 1`.
// Spec: docs/log-format.md §2. Keys are lower_snake_case; values are free text without newlines.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace driftlab::host {

/// Ordered key -> value map with typed accessors. Order is kept so a log round-trips byte for byte.
class LogMetadata {
public:
    /// Sets `key` (replacing an earlier value in place). Throws UsageError on a key that is not
    /// lower_snake_case or a value with a newline, because the file could not be read back.
    void set(const std::string& key, const std::string& value);
    void set(const std::string& key, double value);
    void set(const std::string& key, std::int64_t value);

    bool has(const std::string& key) const;
    /// The value text, or nullopt when absent.
    std::optional<std::string> get(const std::string& key) const;
    /// The value as a finite number; nullopt when absent or not a number.
    std::optional<double> get_double(const std::string& key) const;
    /// The value as an integer; nullopt when absent or not an integer.
    std::optional<std::int64_t> get_int(const std::string& key) const;

    const std::vector<std::pair<std::string, std::string>>& entries() const { return entries_; }
    /// The file line `key` was read from (1-based, set by the reader), for messages; 0 when not read from a file.
    std::uint64_t line_of(const std::string& key) const;
    void set_line(const std::string& key, std::uint64_t line);
    bool empty() const { return entries_.empty(); }

    /// True when `key` can be written: [a-z0-9_]+ starting with a letter, and not the reserved `gap`.
    static bool is_valid_key(const std::string& key);
    /// A value is one line: no carriage return or line feed (a reader taking one from a file refuses it first).
    static bool is_valid_value(const std::string& value);

private:
    std::vector<std::pair<std::string, std::string>> entries_;
    std::vector<std::pair<std::string, std::uint64_t>> lines_;
};

}  // namespace driftlab::host
