// A file's FNV-1a; see fnv1a.hpp.
#include "host/util/fnv1a.hpp"

#include <fstream>

namespace driftlab::host {

std::string file_fingerprint(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "";
    Fnv1a h;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
        h.add(std::string_view(buffer, static_cast<std::size_t>(in.gcount())));
    return in.bad() ? "" : h.hex();
}

}  // namespace driftlab::host
