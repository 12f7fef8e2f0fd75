// Stable-key JSON output for every analysis command (`--json`). docs/analysis.md §5 lists the keys.
// JSON has no NaN or infinity: such values are written as null, so a consumer sees "not determined".
#pragma once

#include <ostream>
#include <vector>

#include <nlohmann/json.hpp>

namespace driftlab::host::view {

/// A number, or null when not finite.
nlohmann::json json_number(double value);

/// An array of numbers (non-finite entries null).
nlohmann::json json_array(const std::vector<double>& values);

/// Pretty-prints `value` (2-space indent) and a newline: the one format every command uses.
void write_json(std::ostream& out, const nlohmann::json& value);

}  // namespace driftlab::host::view
