// The calibration `calibrate` wrote, as a table a person reads (docs/calibration.md).
#pragma once

#include <ostream>
#include <string>

#include "host/cal/calibration.hpp"

namespace driftlab::host::view {

/// Per channel C1, C2 [counts] and T [s] with their 95 % intervals and what the board refers the channel to; then the
/// id and where it was written.
void print_calibration(std::ostream& out, const cal::Calibration& calibration, const std::string& path);

}  // namespace driftlab::host::view
