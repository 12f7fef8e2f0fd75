// ByteLink: the byte pipe between the host and a board (serial port, pseudo-terminal, or an in-process link
// in tests and benchmarks). The host protocol client (board_client.hpp) talks through it only.
//
// Losing the link (an unplugged adapter, a closed pseudo-terminal) is a result, not an exception, so the
// recorder can reconnect; failures that end the command are thrown by whoever opens the link.
#pragma once

#include <cstddef>
#include <cstdint>

namespace driftlab::host::io {

enum class LinkStatus : std::uint8_t {
    ok,       ///< bytes moved (possibly zero for a read)
    timeout,  ///< nothing arrived within the timeout
    lost,     ///< the device went away (hang-up, I/O error); reopen to continue
};

struct ReadResult {
    std::size_t bytes = 0;
    LinkStatus status = LinkStatus::ok;
};

class ByteLink {
public:
    virtual ~ByteLink() = default;
    /// Writes all `count` bytes or reports the link lost.
    virtual LinkStatus write(const std::uint8_t* bytes, std::size_t count) = 0;
    /// Waits up to `timeout_ms` [ms] for data and reads what is there, at most `capacity` bytes.
    virtual ReadResult read(std::uint8_t* out, std::size_t capacity, int timeout_ms) = 0;
};

}  // namespace driftlab::host::io
