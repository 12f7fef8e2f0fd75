// A board's 128-bit command key as the host side keeps it (a value it can copy and compare), and its bytes as the
// protocol library takes them (proto::Key, the C array the firmware shares): the one place that turns the first into
// the second, for CommandAuth, the key record and the cycle budget alike (docs/security.md).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>

#include "driftlab/proto/command_auth.hpp"

namespace driftlab::sim {

using BoardKey = std::array<std::uint8_t, auth::kKeyBytes>;

/// The bytes of `key`; get() is null where there is no key (an open board, whose commands carry a zero tag).
class KeyBytes {
public:
    explicit KeyBytes(const std::optional<BoardKey>& key) : set_(key.has_value()) {
        if (key) std::copy(key->begin(), key->end(), bytes_);
    }
    const proto::Key* get() const { return set_ ? &bytes_ : nullptr; }

private:
    proto::Key bytes_{};
    bool set_;
};

}  // namespace driftlab::sim
