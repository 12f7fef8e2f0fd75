// Opening input files; see input_file.hpp.
#include "host/util/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "host/util/error.hpp"

namespace driftlab::host {

std::ifstream open_input_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw DataError(path, 0, std::string("cannot open: ") + std::strerror(errno));
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw DataError(path, 0, "is a folder, not a file");
    return in;
}

}  // namespace driftlab::host
