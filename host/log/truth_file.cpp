// The ground truth file; see truth_file.hpp.
#include "host/log/truth_file.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "host/log/log_reader.hpp"
#include "host/log/numeric_table.hpp"
#include "host/util/error.hpp"

namespace driftlab::host {
namespace {

std::vector<double> column(const NumericTable& table, const std::string& path, const char* name) {
    for (std::size_t i = 0; i < table.names.size(); ++i)
        if (table.names[i] == name) return table.columns[i];
    throw DataError(path, table.line_of_row(0) > 1 ? table.line_of_row(0) - 1 : 0,
                    std::string("the ground truth has no column '") + name +
                        "' (header t_s,x_m,y_m,heading_deg,speed_mps,yaw_rate_dps,accel_x_g,accel_y_g,accel_z_g; "
                        "docs/log-format.md §9)");
}

std::string seconds(double t_s) {
    char text[40];
    std::snprintf(text, sizeof text, "%.6f s", t_s);
    return text;
}

}  // namespace

TruthFile read_truth_file(const std::string& path) {
    const NumericTable table = read_numeric_table(path);
    TruthFile truth;
    truth.path = path;
    for (const std::string& comment : table.comments) {
        const auto kv = split_comment_key_value(comment);
        if (kv && kv->first == "trajectory") truth.trajectory = kv->second;
        if (kv && kv->first == "rest_before_s") truth.rest_before_s = std::strtod(kv->second.c_str(), nullptr);
    }
    truth.t_s = column(table, path, "t_s");
    truth.x_m = column(table, path, "x_m");
    truth.y_m = column(table, path, "y_m");
    truth.heading_deg = column(table, path, "heading_deg");
    truth.speed_mps = column(table, path, "speed_mps");
    truth.yaw_rate_dps = column(table, path, "yaw_rate_dps");
    truth.accel_x_g = column(table, path, "accel_x_g");
    truth.accel_y_g = column(table, path, "accel_y_g");
    truth.accel_z_g = column(table, path, "accel_z_g");
    truth.lines = table.row_lines;
    for (std::size_t i = 1; i < truth.size(); ++i)
        if (!(truth.t_s[i] > truth.t_s[i - 1]))
            throw DataError(path, table.line_of_row(i),
                            "t_s " + seconds(truth.t_s[i]) + " does not follow " + seconds(truth.t_s[i - 1]));
    return truth;
}

std::vector<std::size_t> match_truth_rows(const TruthFile& truth, const LogData& log, bool log_cut) {
    // The truth prints t_s to the microsecond; the log's own times are exact ticks.
    constexpr double kSameTimeS = 1.5e-6;
    std::vector<std::size_t> rows;
    rows.reserve(log.size());
    std::size_t j = 0;
    for (std::size_t k = 0; k < log.size(); ++k) {
        const double t = log.t_s[k];
        if (!log_cut && j < truth.size() && truth.t_s[j] < t - kSameTimeS)
            throw DataError(truth.path, truth.lines[j],
                            "the truth's row at " + seconds(truth.t_s[j]) + " has no row in " + log.source_name +
                                " (is this the truth of that log?)");
        while (j < truth.size() && truth.t_s[j] < t - kSameTimeS) ++j;
        if (j == truth.size() || std::fabs(truth.t_s[j] - t) > kSameTimeS)
            throw DataError(truth.path, j < truth.size() ? truth.lines[j] : 0,
                            "no row at " + seconds(t) + ", the time of a row of " + log.source_name +
                                " (is this the truth of that log?)");
        rows.push_back(j++);
    }
    if (!log_cut && j < truth.size())
        throw DataError(truth.path, truth.lines[j],
                        "the truth goes on after the last row of " + log.source_name + " (" + seconds(log.t_s.back()) +
                            "): is this the truth of that log?");
    return rows;
}

}  // namespace driftlab::host
