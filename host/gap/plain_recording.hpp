// A recording that is not a canonical log (a plain table of sensor values, such as a third-party logger's file)
// turned into the log the diagnosis reads: each mapped column becomes integer codes of its LSB around mid-scale,
// and blocks of consecutive samples are averaged, which is the firmware's order-0 least-squares smoother with
// window = conversions per output = the block. docs/gap.md §Usage.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "driftlab/channels.hpp"
#include "host/log/log_data.hpp"
#include "host/log/numeric_table.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::host::gap {

/// The `source` a plain recording's LogData carries: rows without frames or sequence numbers of their own.
inline constexpr const char* kPlainRecordingSource = "plain recording";

/// One column of the table analysed as one channel of the unit.
struct ColumnMapping {
    Channel channel = Channel::gyro;
    std::string column;  ///< the table's column name ("col1"... for a table without a name line)
    double lsb = 0.0;    ///< the column's value of one code (its resolution), > 0
    /// The column's unit in the simulator's (deg/s for the gyro, g for an accelerometer): 180/pi for rad/s.
    double to_model_unit = 1.0;
};

/// Parses `CHANNEL=COLUMN:LSB[:UNIT]` (e.g. `gyro=col1:0.00875`, `gyro=gx:1.33e-4:rad/s`); UNIT is deg/s (the
/// default), mdps or rad/s for the gyro, g (the default), mg or m/s2 for an accelerometer. Throws UsageError naming
/// what is wrong.
ColumnMapping parse_column_mapping(const std::string& text);

struct PlainRecording {
    std::vector<ColumnMapping> columns;  ///< at least one, each channel at most once
    double sample_period_s = 0.0;  ///< the raw samples' period (required; timing comes from a t_s/t/time column if any)
    std::size_t block = 1;         ///< samples averaged per output
};

/// The log of `table` under `how`. Channels without a column stay constant at mid-scale (not analysed). Throws
/// UsageError for a bad mapping, DataError (file) for a table too short for one block or a column whose codes leave
/// the 10-bit range around mid-scale (a coarser LSB is needed).
LogData log_from_table(const NumericTable& table, const PlainRecording& how);

/// The unit that `log` (made by log_from_table() under `how`) reads as: on each mapped channel one code is one LSB
/// of the column (converted to deg/s or g) and mid-scale is the column's median (metadata `mid_scale_value_<channel>`),
/// so that the diagnosis's physical parameters (deg/s, g) are the recording's own and a model file written from it
/// describes the recorded sensor. The other channels and everything else are `unit`'s; the converter is 10-bit, as the
/// codes.
sim::SimModel unit_of_recording(sim::SimModel unit, const PlainRecording& how, const LogData& log);

}  // namespace driftlab::host::gap
