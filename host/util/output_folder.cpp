// make_output_folder(), NewFolders; see output_folder.hpp.
#include "host/util/output_folder.hpp"

#include <system_error>

#include "host/util/error.hpp"

namespace driftlab::host {

void make_output_folder(const std::string& dir, const std::string& what) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw DeviceError(dir, "cannot create the " + what + " folder: " + ec.message());
}

void make_folder_of(const std::string& path, const std::string& what) {
    const std::string dir = std::filesystem::path(path).parent_path().string();
    if (!dir.empty()) make_output_folder(dir, what);
}

NewFolders::~NewFolders() {
    for (auto it = made_.rbegin(); it != made_.rend(); ++it) {
        std::error_code ec;
        // A folder is removed only when empty: what is in it stays, and so do its parents
        std::filesystem::remove(*it, ec);
    }
}

void NewFolders::make_folder_of(const std::string& path, const std::string& what) {
    std::vector<std::filesystem::path> missing;  // innermost first
    std::error_code ec;
    for (std::filesystem::path dir = std::filesystem::path(path).parent_path();
         !dir.empty() && !std::filesystem::exists(dir, ec); dir = dir.parent_path()) {
        missing.push_back(dir);
        if (dir == dir.parent_path()) break;  // a root
    }
    // Noted before they are made: those made before a failure are removed too.
    made_.insert(made_.end(), missing.rbegin(), missing.rend());
    host::make_folder_of(path, what);
}

}  // namespace driftlab::host
