// Channel names as users type them (--as, --channel, a series' name): the one lookup from text to Channel, so every
// command accepts and lists exactly kChannelNames (common/include/driftlab/channels.hpp).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "driftlab/channels.hpp"

namespace driftlab::host {

/// The channel whose kChannelNames entry is exactly `name` (case and all); nullopt for any other text.
std::optional<Channel> channel_named(std::string_view name);

/// Every channel name in Channel order, joined by ", " ("gyro, accel_x, accel_y, accel_z"): what an error for an
/// unknown name offers instead.
std::string channel_name_list();

}  // namespace driftlab::host
