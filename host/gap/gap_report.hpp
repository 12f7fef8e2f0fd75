// The readable report of `driftlab gap --report DIR`: DIR/gap.md with the verdict, located cells, candidates and
// plots (gnuplot through host/report) of the residual Allan deviation of the real log against the band of the
// base simulator and of the simulator with the accepted effects. docs/gap.md §Report.
#pragma once

#include <string>

#include "host/gap/diagnose.hpp"
#include "host/log/log_data.hpp"

namespace driftlab::host::gap {

/// Writes DIR/gap.md and DIR/gap_adev_<channel>.png/.svg (plots skipped with a note when gnuplot is missing).
void write_gap_report(const GapResult& result, const LogData& log, const std::string& dir, const GapOptions& options);

}  // namespace driftlab::host::gap
