// Folders a command writes its outputs into (reports, plots, logs).
#pragma once

#include <string>

namespace driftlab::host {

/// Creates `dir` and its parents when missing. Throws DeviceError naming the folder, what it is for (`what`:
/// "report", "plot"...) and the system's reason when it cannot be made (a file in the way, no permission), so that
/// no command fails with a bare filesystem exception or only after its work is done.
void make_output_folder(const std::string& dir, const std::string& what);

/// make_output_folder() for the folder that holds the file `path` (none when `path` names no folder).
void make_folder_of(const std::string& path, const std::string& what);

}  // namespace driftlab::host
