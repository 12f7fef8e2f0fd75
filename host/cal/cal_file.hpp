// CAL.json: a Calibration as a file the user keeps, reads and edits (docs/calibration.md "The file").
#pragma once

#include <string>

#include "host/cal/calibration.hpp"

namespace driftlab::host::cal {

/// The file's JSON text: `driftlab_calibration` (format 1), `cal_id`, `source`, and per channel C1, C2 [counts],
/// T [s], zero and the 95 % intervals.
std::string calibration_json(const Calibration& cal);

/// Writes calibration_json() to `path` whole (write, then rename). Throws DeviceError when it cannot.
void write_calibration(const std::string& path, const Calibration& cal);

/// Reads a CAL.json. Throws DataError naming the file and the key ("channels.gyro.T: not a number") for a file that
/// is not one, and for values outside what a board accepts (to_payloads()).
Calibration read_calibration(const std::string& path);

}  // namespace driftlab::host::cal
