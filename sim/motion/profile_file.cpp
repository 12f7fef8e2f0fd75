// Reading a trajectory profile file; see profile_file.hpp.
#include "sim/motion/profile_file.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <string_view>

#include "sim/sim_error.hpp"

namespace driftlab::sim {
namespace {

constexpr std::array<std::string_view, 3> kColumns = {"t_s", "speed_mps", "yaw_rate_dps"};

struct Row {
    double t_s, speed_mps, yaw_rate_dps;
    int line;
};

std::string text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::vector<std::string_view> fields_of(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ',' || line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ',' && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

// Which field holds each of kColumns.
std::array<std::size_t, 3> read_header(const std::vector<std::string_view>& fields, const std::string& where) {
    std::array<std::size_t, 3> at{};
    for (std::size_t c = 0; c < kColumns.size(); ++c) {
        std::size_t found = fields.size();
        for (std::size_t f = 0; f < fields.size(); ++f)
            if (fields[f] == kColumns[c]) found = f;
        if (found == fields.size() || fields.size() != kColumns.size())
            throw ModelFileError(where, "header", "expected the columns t_s, speed_mps and yaw_rate_dps");
        at[c] = found;
    }
    return at;
}

double number(std::string_view text, std::string_view column, const std::string& where) {
    double v = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
        throw ModelFileError(where, std::string(column), "expected a finite number, got '" + std::string(text) + "'");
    return v;
}

// Between two rows speed and yaw rate change linearly: the forward and lateral specific forces are largest at an end.
ProfileSegment segment_between(const Row& a, const Row& b, const std::string& path) {
    const std::string where = path + ":" + std::to_string(b.line);
    const double dt = b.t_s - a.t_s;
    if (!(dt > 0.0)) throw ModelFileError(where, "t_s", "time " + text(b.t_s) + " is not after the previous row's");
    const ProfileSegment s{dt, a.speed_mps, (b.speed_mps - a.speed_mps) / dt, a.yaw_rate_dps,
                           (b.yaw_rate_dps - a.yaw_rate_dps) / dt};
    const double lateral_g = std::max(std::abs(a.speed_mps * a.yaw_rate_dps), std::abs(b.speed_mps * b.yaw_rate_dps)) *
                             std::numbers::pi / 180.0 / kStandardGravity;
    if (std::abs(s.accel_mps2) / kStandardGravity > kMaxProfileAccelG || lateral_g > kMaxProfileAccelG)
        throw ModelFileError(where, "speed_mps",
                             "the acceleration to this row exceeds " + text(kMaxProfileAccelG) + " g");
    return s;
}

}  // namespace

std::vector<ProfileSegment> read_profile_file(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw ModelFileError(path, "trajectory", "cannot open the file");
    std::vector<Row> rows;
    std::array<std::size_t, 3> at{};
    bool header = false;
    int line_no = 0;
    for (std::string line; std::getline(in, line);) {
        ++line_no;
        const std::vector<std::string_view> f = fields_of(line);
        if (f.empty() || f[0].starts_with('#')) continue;
        const std::string where = path + ":" + std::to_string(line_no);
        if (!header) {
            at = read_header(f, where);
            header = true;
            continue;
        }
        if (f.size() != kColumns.size())
            throw ModelFileError(where, "row", "expected 3 fields, got " + std::to_string(f.size()));
        Row r{number(f[at[0]], kColumns[0], where), number(f[at[1]], kColumns[1], where),
              number(f[at[2]], kColumns[2], where), line_no};
        if (rows.empty() && r.t_s != 0.0) throw ModelFileError(where, "t_s", "the first row's time must be 0");
        if (std::abs(r.yaw_rate_dps) > kMaxProfileYawRateDps)
            throw ModelFileError(where, "yaw_rate_dps", "beyond ±" + text(kMaxProfileYawRateDps) + " deg/s");
        rows.push_back(r);
    }
    if (!header) throw ModelFileError(path, "header", "no header line (t_s, speed_mps, yaw_rate_dps)");
    if (rows.size() < 2) throw ModelFileError(path, "rows", "a profile needs at least two rows");
    std::vector<ProfileSegment> segments;
    for (std::size_t k = 1; k < rows.size(); ++k) segments.push_back(segment_between(rows[k - 1], rows[k], path));
    return segments;
}

}  // namespace driftlab::sim
