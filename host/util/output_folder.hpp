// Folders a command writes its outputs into (reports, plots, logs).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace driftlab::host {

/// Creates `dir` and its parents when missing. Throws DeviceError naming the folder, what it is for (`what`:
/// "report", "plot"...) and the system's reason when it cannot be made (a file in the way, no permission), so that
/// no command fails with a bare filesystem exception or only after its work is done.
void make_output_folder(const std::string& dir, const std::string& what);

/// make_output_folder() for the folder that holds the file `path` (none when `path` names no folder).
void make_folder_of(const std::string& path, const std::string& what);

/// make_folder_of() for a command that may still be refused after making its folders (`record`: a port that
/// cannot be opened, a device that is no board): unless keep() is called, the destructor removes the folders this
/// made itself, deepest first and each only while empty, so that a refusal leaves no empty folders behind and never
/// touches one that was there before.
class NewFolders {
public:
    NewFolders() = default;
    NewFolders(const NewFolders&) = delete;
    NewFolders& operator=(const NewFolders&) = delete;
    ~NewFolders();

    void make_folder_of(const std::string& path, const std::string& what);
    /// The command has written into them: they stay.
    void keep() { made_.clear(); }

private:
    std::vector<std::filesystem::path> made_;  ///< in the order made, parents first
};

}  // namespace driftlab::host
