// The ground truth beside a log in motion (`LOG.truth.csv`, docs/log-format.md §9), read back for the analyses that
// take the known input out (`gap --truth`) and checked row by row against its log.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "host/log/log_data.hpp"

namespace driftlab::host {

struct TruthFile {
    std::string path;
    std::string trajectory;      ///< its `# trajectory:` line ("" when absent): a built-in name or a profile file
    double rest_before_s = 0.0;  ///< its `# rest_before_s:` line
    std::vector<double> t_s;     ///< the board's clock, as the log's rows
    std::vector<double> x_m, y_m, heading_deg, speed_mps, yaw_rate_dps;
    std::vector<double> accel_x_g, accel_y_g, accel_z_g;  ///< body-frame specific force [g]
    std::vector<std::uint64_t> lines;                     ///< the file line of each row

    std::size_t size() const { return t_s.size(); }
};

/// Reads `path`. Throws DataError naming the file and line on a missing column, a bad number or times that do not
/// increase.
TruthFile read_truth_file(const std::string& path);

/// The truth row of each of `log`'s rows (same t_s to the truth's microsecond). Every log row must have one; without
/// `log_cut` (the log as recorded, no rows left out) the truth may have no other rows. Throws DataError naming the
/// truth file's line (or, for a log row it lacks, the log's time) where they part.
std::vector<std::size_t> match_truth_rows(const TruthFile& truth, const LogData& log, bool log_cut);

}  // namespace driftlab::host
