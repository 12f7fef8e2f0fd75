// The units a user may name for a gyro's or an accelerometer's samples, with their SI value: one table for every
// command that reads a plain recording (allan and report --unit, gap --as ...:UNIT), so that they accept the same
// spellings.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "driftlab/channels.hpp"
#include "host/stats/noise_terms.hpp"
#include "host/stats/phase_record.hpp"

namespace driftlab::host::stats {

struct RateUnit {
    std::string name;       ///< canonical spelling, for output (m/s^2 for m/s2)
    RateQuantity quantity;  ///< angular_rate or acceleration
    double si_per_unit;     ///< rad/s or m/s^2 per unit
};

/// The unit `name` stands for (deg/s, dps, mdps, deg/h, rad/s; g, mg, m/s^2, m/s2, cm/s^2,
/// cm/s2, mm/s^2, mm/s2: the physical units of host/util/units.hpp among them); none when unknown.
std::optional<RateUnit> rate_unit(std::string_view name);

/// The spellings rate_unit() knows for `quantity`, comma-separated, for a message.
std::string rate_unit_names(RateQuantity quantity);

/// The unit of the rate whose phase (integral) samples are in `name`, which their deviations are in: an angle (deg,
/// mdeg, rad) gives an angular rate, a velocity (m/s, cm/s, mm/s) an acceleration, a time (s, ms, us, ns, ps) a
/// clock's fractional frequency labelled by its scale (ns/s: 1e-9), with no navigation quantity; none when unknown.
std::optional<RateUnit> rate_unit_of_phase(std::string_view name);

/// The spellings rate_unit_of_phase() knows, by quantity, for a message ("angle: deg, mdeg, rad; velocity: ...").
std::string phase_unit_names();

/// What a series' samples are, for its noise terms in physical units (physical_terms, kalibr_densities).
struct SampleUnit {
    std::string name;                               ///< the samples' unit, for labels
    RateQuantity quantity = RateQuantity::unknown;  ///< unknown: the unit only labels
    double si_per_unit = 1.0;                       ///< rad/s or m/s^2 per unit
};

/// A log channel's samples: counts, at the channel's physical scale (host/util/units.hpp).
SampleUnit unit_of_channel(Channel c);

/// Samples in the unit `name`: one rate_unit() knows, or another name (or none) that only labels them.
SampleUnit unit_of_name(const std::string& name);

/// One `[COLUMN:]UNIT` value of a --unit option.
struct ColumnUnit {
    std::string column;  ///< "" for every column without its own
    RateUnit unit;
    std::string argument;  ///< the value as given, for messages
};

/// The units `--unit [COLUMN:]UNIT` values give the columns of a plain table.
struct UnitAssignment {
    std::vector<ColumnUnit> units;
    /// `column`'s own unit, else the one for every column; none when neither is given.
    std::optional<RateUnit> for_column(const std::string& column) const;
};

/// Parses the values of `option` (e.g. "--unit"), each `UNIT` or `COLUMN:UNIT` with UNIT the samples' unit: one
/// rate_unit() knows for rate samples, one rate_unit_of_phase() knows for phase samples (whose assignment then holds
/// the rate's unit). Throws UsageError naming the value for an unknown unit (listing the known ones, and for phase
/// samples given a rate's unit, the phase's), an empty column or unit, and a column (or every column) given a unit
/// twice.
UnitAssignment parse_unit_assignment(const std::vector<std::string>& values, const std::string& option,
                                     InputKind kind = InputKind::rate);

/// Throws UsageError for a `COLUMN:UNIT` whose column is not among `columns` (the series of `path` analysed),
/// naming the value and those columns.
void refuse_unknown_columns(const UnitAssignment& units, const std::vector<std::string>& columns,
                            const std::string& path);

/// Standard gravity [m/s^2 per g] (CGPM 1901), which g and mg stand for.
inline constexpr double kStandardGravity = 9.80665;

}  // namespace driftlab::host::stats
