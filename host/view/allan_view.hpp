// The views of the Allan analysis (`driftlab allan`; docs/allan.md): per series the table of each deviation with its
// confidence interval and noise type and the IEEE 952 terms, the JSON, and the plot of the curve with its fit. The
// report's Allan section is allan_section.hpp.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "host/fit/allan_pipeline.hpp"

namespace driftlab::host::view {

/// One series of `driftlab allan --json`: the primary curve (tau, adev, ci_low, ci_high, noise, n, edf, mdev, hdev),
/// terms, kalibr, the sampling and drift fields, and raw where the drift was removed.
nlohmann::json allan_json(const fit::AllanSeriesResult& series);

/// One series as the terminal shows it, headed by the file's `path`.
void print_allan_text(const std::string& path, const fit::AllanSeriesResult& series);

/// allan_<name>.png/.svg in `dir`: the overlapping ADEV with its 68 % interval, the raw curve beside a drift-removed
/// one, and the IEEE 952 fit with each term alone.
void write_allan_plot(const fit::AllanSeriesResult& series, const std::string& dir);

}  // namespace driftlab::host::view
