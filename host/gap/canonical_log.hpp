// A canonical log read for a diagnosis: the simulator must stand beside it, so its converter must be the unit's and
// its metadata must say the smoothing the replicates repeat (gap, fleet).
#pragma once

#include <istream>
#include <string>

#include "host/log/log_data.hpp"
#include "host/log/log_reader.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::host::gap {

/// Parses the canonical log `in` (named `path` in messages) for a diagnosis against `unit`. Throws DataError naming
/// the file (and line) when its adc_bits differ from the unit's, its metadata lack window, fit_order or
/// conversions_per_output, or it was recorded in motion and `with_truth` is false.
LogData read_canonical_log(std::istream& in, const std::string& path, ReadOptions options, const sim::SimModel& unit,
                           bool with_truth);

}  // namespace driftlab::host::gap
