// Who else has a device open: the processes whose descriptors name the same device (/proc/PID/fd), so that a port
// `record` cannot have to itself is refused naming its holder. docs/security.md, docs/recording.md.
#pragma once

#include <string>

namespace driftlab::host::io {

/// "PID 1234 (driftlab record --port /dev/ttyUSB0 ...)" for each other process holding `path` open, "; "-joined;
/// "" when none is found (or /proc is not readable).
std::string port_holders(const std::string& path);

}  // namespace driftlab::host::io
