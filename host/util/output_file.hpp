// Single files a command writes (a model file, a report page): checked before the work that fills them, written
// whole at the end, so that a run neither fails only after its work nor leaves half a file behind.
#pragma once

#include <string>

namespace driftlab::host {

/// Throws DeviceError naming `path`, what it is for (`what`) and the system's reason when no file can be written
/// there (a missing folder, no permission). Leaves no file behind that was not there before.
void check_output_file(const std::string& path, const std::string& what);

/// Writes `text` to `path` through a temporary file beside it and a rename, so that a reader never sees a part of
/// it and an earlier file stays as it was when writing fails. Throws DeviceError as above.
void write_output_file(const std::string& path, const std::string& text, const std::string& what);

}  // namespace driftlab::host
