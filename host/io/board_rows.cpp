// A board's rows in the canonical log; see board_rows.hpp.
#include "host/io/board_rows.hpp"

#include <cmath>

#include "driftlab/proto/temperature.hpp"

namespace driftlab::host::io {
namespace {

// A code's temperature to 0.1 °C: the sensor's steps are about 1 °C, its uncalibrated error ±10 °C.
double temperature_c(std::uint16_t code) {
    if (code == proto::kNoTemperature) return kNoTemperatureC;
    return std::round(proto::celsius_of_temperature_code(code) * 10.0) / 10.0;
}

}  // namespace

std::vector<std::string> board_columns(bool raw, bool flags) {
    std::vector<std::string> c = {"tick", "sat_flags", "n_window", "dropped", "temp_c"};
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
                           static_cast<double>(r.n_window), static_cast<double>(r.dropped), temperature_c(r.temp_code)};
    if (!raw) return row;
    for (std::uint16_t code : r.raw_counts) row.optional_values.push_back(r.has_raw ? code : kLostRawCode);
    if (flags) row.optional_values.push_back(r.has_raw ? 0.0 : static_cast<double>(kFlagRawMissing));
    return row;
}

}  // namespace driftlab::host::io
