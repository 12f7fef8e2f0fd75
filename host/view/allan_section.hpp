// The Allan part of the HTML report: overlapping ADEV of each channel before and after removing the fitted
// drift (eq. 1), with confidence intervals and the IEEE 952 noise terms (host/stats/allan_analysis.hpp,
// noise_terms.hpp; docs/allan.md). Removing the deterministic turn-on drift first keeps it from masquerading as
// rate random walk or ramp at long tau. Headers carry the samples' unit; where a channel is a rate gyro or an
// accelerometer, its terms come again in navigation units (deg/sqrt(h), deg/h; m/s/sqrt(h), mg; docs/analysis.md §6).
#pragma once

#include <string>
#include <vector>

#include "host/fit/drift_analysis.hpp"
#include "host/view/gnuplot.hpp"

namespace driftlab::host::view {

struct AllanSection {
    std::string html;         ///< tables (no plots)
    std::vector<Plot> plots;  ///< one ADEV plot per channel
    std::vector<std::string> plot_names;
};

/// Builds the section for the analysed channels, in counts for a log's channels, else in their data.unit
/// (report --unit; stats::unit_of_name). tau0 is stats::grid_period_s of each channel's times (the median
/// spacing, the mean for rows in bursts); a channel whose grid is more than 20 % gaps gets a warning.
AllanSection allan_section(const std::vector<const fit::DriftAnalysis*>& channels);

}  // namespace driftlab::host::view
