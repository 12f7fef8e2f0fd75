// A board's rows in the canonical log; see board_rows.hpp.
#include "host/io/board_rows.hpp"

namespace driftlab::host::io {

std::vector<std::string> board_columns(bool raw, bool flags) {
    std::vector<std::string> c = {"tick", "sat_flags", "n_window", "dropped"};
    if (raw)
        for (const char* name : kChannelNames) c.push_back(std::string("raw_") + name);
    if (raw && flags) c.emplace_back("flags");
    return c;
}

LogRow board_log_row(const receiver::Row& r, bool raw, bool flags) {
    LogRow row;
    row.t_s = r.t_s;
    row.seq = r.seq;
    row.counts = r.value_counts;
    row.optional_values = {static_cast<double>(r.tick), static_cast<double>(r.sat_flags),
                           static_cast<double>(r.n_window), static_cast<double>(r.dropped)};
    if (!raw) return row;
    for (std::uint16_t code : r.raw_counts) row.optional_values.push_back(r.has_raw ? code : kLostRawCode);
    if (flags) row.optional_values.push_back(r.has_raw ? 0.0 : static_cast<double>(kFlagRawMissing));
    return row;
}

}  // namespace driftlab::host::io
