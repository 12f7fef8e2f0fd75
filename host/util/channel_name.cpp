// Channel names as users type them; see channel_name.hpp.
#include "host/util/channel_name.hpp"

#include <cstdint>

namespace driftlab::host {

std::optional<Channel> channel_named(std::string_view name) {
    for (std::uint8_t c = 0; c < kChannelCount; ++c)
        if (name == kChannelNames[c]) return static_cast<Channel>(c);
    return std::nullopt;
}

std::string channel_name_list() {
    std::string out;
    for (const char* name : kChannelNames) out += (out.empty() ? "" : ", ") + std::string(name);
    return out;
}

}  // namespace driftlab::host
