// A capture as the log readers know it; see capture_file.hpp.
#include "host/log/capture_file.hpp"

namespace driftlab::host {

std::string default_capture_path(const std::string& log_path) { return log_path + ".cap"; }

bool starts_as_capture(std::istream& in) {
    std::string first;
    return std::getline(in, first) && first.rfind(kCaptureMagicKey, 0) == 0;
}

}  // namespace driftlab::host
