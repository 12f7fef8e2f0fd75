// JSON helpers; see json_out.hpp.
#include "host/view/json_out.hpp"

#include <cmath>

namespace driftlab::host::view {

nlohmann::json json_number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

nlohmann::json json_array(const std::vector<double>& values) {
    nlohmann::json out = nlohmann::json::array();
    for (double v : values) out.push_back(json_number(v));
    return out;
}

void write_json(std::ostream& out, const nlohmann::json& value) { out << value.dump(2) << '\n'; }

}  // namespace driftlab::host::view
