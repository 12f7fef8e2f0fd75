// Where a capture's frames failed their CRC check; see crc_failures.hpp.
#include "host/io/crc_failures.hpp"

#include <algorithm>
#include <cstdio>

namespace driftlab::host::io {

void CrcFailures::warn(const std::string& capture) const {
    if (seen_ == 0) return;
    const std::size_t named = std::min(records_.size(), kNamed);
    std::string where;
    for (std::size_t i = 0; i < named; ++i) where += (where.empty() ? "" : ", ") + std::to_string(records_[i].offset);
    const bool one = seen_ == 1;
    std::fprintf(stderr, "driftlab: warning: %s: %u %s CRC check and %s as lost (in the %s at byte %s %s%s)\n",
                 capture.c_str(), static_cast<unsigned>(seen_), one ? "frame failed its" : "frames failed their",
                 one ? "counts" : "count", named == 1 ? "record" : "records", named == 1 ? "offset" : "offsets",
                 where.c_str(), records_.size() > named ? " and later ones" : "");
}

nlohmann::json CrcFailures::json() const {
    nlohmann::json out = nlohmann::json::array();
    for (const Located& r : records_) out.push_back({{"offset", r.offset}, {"frames", r.frames}});
    return out;
}

}  // namespace driftlab::host::io
