// Compensation state of a log (compensation.hpp).
#include "host/log/compensation.hpp"

#include "driftlab/proto/messages.hpp"

namespace driftlab::host {

std::optional<std::string> compensated_on_board(const LogMetadata& metadata) {
    const std::optional<std::string> state = metadata.get("cal_state");
    const std::string active = proto::cal_state_name(static_cast<std::uint8_t>(proto::CalState::active));
    const std::string settled = proto::cal_state_name(static_cast<std::uint8_t>(proto::CalState::settled));
    if (!state || (*state != active && *state != settled)) return std::nullopt;
    const std::optional<std::int64_t> id = metadata.get_int("cal_id");
    return "its outputs were compensated on board (calibration " + (id ? std::to_string(*id) : std::string("?")) +
           (*state == settled ? ", after a warm restart: the transient taken as over)" : ")");
}

}  // namespace driftlab::host
