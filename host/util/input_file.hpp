// Opening a file a command reads: one place that says why it cannot be read.
#pragma once

#include <fstream>
#include <string>

namespace driftlab::host {

/// Opens `path` for binary reading. Throws DataError(path, 0, ...) when it is missing or unreadable (the system's
/// reason) or a folder (which a stream opens, and then reads as an empty file).
std::ifstream open_input_file(const std::string& path);

}  // namespace driftlab::host
