// The plots of a gap result's report (gap_view.hpp): the real log's eq. 1 residual against the replicate bands of the
// base simulator and of the simulator with the added effects. Internal to host/view.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "host/gap/diagnose.hpp"
#include "host/log/log_data.hpp"

namespace driftlab::host::view {

/// gap.md's section of plots: for each analysed channel its residual's Allan deviation by octave and mean over time,
/// and for a raw-mode channel the share of rows on each code, each against the bands, written into `dir`.
void write_residual_plots(std::ostream& md, const gap::GapResult& result, const LogData& log, const std::string& dir,
                          const gap::GapOptions& options);

/// Every file write_residual_plots() may write into `dir`, whichever channels it plots.
std::vector<std::string> residual_plot_files(const std::string& dir);

}  // namespace driftlab::host::view
