// make_output_folder(); see output_folder.hpp.
#include "host/util/output_folder.hpp"

#include <filesystem>
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

}  // namespace driftlab::host
