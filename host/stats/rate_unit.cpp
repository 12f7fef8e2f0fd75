// Rate units by name; see rate_unit.hpp.
#include "host/stats/rate_unit.hpp"

#include <algorithm>
#include <array>
#include <numbers>

#include "host/util/error.hpp"
#include "host/util/units.hpp"

namespace driftlab::host::stats {

namespace {

struct Entry {
    std::string_view spelling;
    std::string_view name;
    RateQuantity quantity;
    double si_per_unit;
};

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr std::array<Entry, 13> kUnits{{
    {"deg/s", "deg/s", RateQuantity::angular_rate, kDeg},
    {"dps", "deg/s", RateQuantity::angular_rate, kDeg},
    {"mdps", "mdps", RateQuantity::angular_rate, kDeg * 1e-3},
    {"deg/h", "deg/h", RateQuantity::angular_rate, kDeg / 3600.0},
    {"rad/s", "rad/s", RateQuantity::angular_rate, 1.0},
    {"g", "g", RateQuantity::acceleration, kStandardGravity},
    {"mg", "mg", RateQuantity::acceleration, kStandardGravity * 1e-3},
    {"m/s^2", "m/s^2", RateQuantity::acceleration, 1.0},
    {"m/s2", "m/s^2", RateQuantity::acceleration, 1.0},
    {"cm/s^2", "cm/s^2", RateQuantity::acceleration, 0.01},
    {"cm/s2", "cm/s^2", RateQuantity::acceleration, 0.01},
    {"mm/s^2", "mm/s^2", RateQuantity::acceleration, 1e-3},
    {"mm/s2", "mm/s^2", RateQuantity::acceleration, 1e-3},
}};

// Phase samples by their unit, with the unit of their rate (a spelling of kUnits, or a clock's fractional frequency).
struct PhaseEntry {
    std::string_view spelling;
    std::string_view rate;
    std::string_view quantity;  ///< for a message
};

constexpr std::array<PhaseEntry, 11> kPhaseUnits{{
    {"deg", "deg/s", "angle"},
    {"mdeg", "mdps", "angle"},
    {"rad", "rad/s", "angle"},
    {"m/s", "m/s^2", "velocity"},
    {"cm/s", "cm/s^2", "velocity"},
    {"mm/s", "mm/s^2", "velocity"},
    {"s", "s/s", "time"},
    {"ms", "ms/s", "time"},
    {"us", "us/s", "time"},
    {"ns", "ns/s", "time"},
    {"ps", "ps/s", "time"},
}};

}  // namespace

std::string phase_unit_names() {
    std::string names;
    std::string_view quantity;
    for (const PhaseEntry& e : kPhaseUnits) {
        if (e.quantity != quantity)
            names += (names.empty() ? "" : "; ") + std::string(e.quantity) + ": ";
        else
            names += ", ";
        names += e.spelling;
        quantity = e.quantity;
    }
    return names;
}

std::optional<RateUnit> rate_unit_of_phase(std::string_view name) {
    for (const PhaseEntry& e : kPhaseUnits) {
        if (e.spelling != name) continue;
        if (const auto rate = rate_unit(e.rate)) return rate;
        return RateUnit{std::string(e.rate), RateQuantity::unknown, 1.0};  // a clock's: no navigation terms
    }
    return std::nullopt;
}

std::optional<RateUnit> rate_unit(std::string_view name) {
    for (const Entry& e : kUnits)
        if (e.spelling == name) return RateUnit{std::string(e.name), e.quantity, e.si_per_unit};
    return std::nullopt;
}

std::string rate_unit_names(RateQuantity quantity) {
    std::string names;
    for (const Entry& e : kUnits)
        if (e.quantity == quantity) names += (names.empty() ? "" : ", ") + std::string(e.spelling);
    return names;
}

std::optional<RateUnit> UnitAssignment::for_column(const std::string& column) const {
    std::optional<RateUnit> every;
    for (const ColumnUnit& u : units) {
        if (u.column == column) return u.unit;
        if (u.column.empty()) every = u.unit;
    }
    return every;
}

UnitAssignment parse_unit_assignment(const std::vector<std::string>& values, const std::string& option,
                                     InputKind kind) {
    UnitAssignment out;
    for (const std::string& value : values) {
        const std::string named = option + " '" + value + "'";
        // A unit holds no colon (m/s^2, deg/s), so the last one ends a column name.
        const auto colon = value.rfind(':');
        const std::string column = colon == std::string::npos ? "" : value.substr(0, colon);
        const std::string name = colon == std::string::npos ? value : value.substr(colon + 1);
        if (colon != std::string::npos && column.empty())
            throw UsageError(named + ": no column before ':' (COLUMN:UNIT, or UNIT alone for every column)");
        const bool phase = kind == InputKind::phase;
        const auto unit = phase ? rate_unit_of_phase(name) : rate_unit(name);
        if (!unit && phase)
            // A rate's unit had been the only kind --unit knew; for phase samples it is their integral's.
            throw UsageError(
                named + ": " + (name.empty() ? "no unit" : "unknown unit '" + name + "'") + " for phase samples" +
                (rate_unit(name) ? " ('" + name + "' is a rate's: give its integral's, e.g. deg for deg/s)" : "") +
                "; " + phase_unit_names());
        if (!unit)
            throw UsageError(named + ": " + (name.empty() ? "no unit" : "unknown unit '" + name + "'") +
                             "; angular rate: " + rate_unit_names(RateQuantity::angular_rate) +
                             "; acceleration: " + rate_unit_names(RateQuantity::acceleration));
        for (const ColumnUnit& earlier : out.units)
            if (earlier.column == column)
                throw UsageError(named + ": " + (column.empty() ? "every column" : "column '" + column + "'") +
                                 " already has a unit (" + option + " '" + earlier.argument + "')");
        out.units.push_back({column, *unit, value});
    }
    return out;
}

void refuse_unknown_columns(const UnitAssignment& units, const std::vector<std::string>& columns,
                            const std::string& path) {
    for (const ColumnUnit& u : units.units) {
        if (u.column.empty() || std::find(columns.begin(), columns.end(), u.column) != columns.end()) continue;
        std::string listed;
        for (const std::string& c : columns) listed += (listed.empty() ? "" : ", ") + c;
        throw UsageError("--unit '" + u.argument + "': " + path + " has no column '" + u.column +
                         "' among those analysed (" + listed + ")");
    }
}

SampleUnit unit_of_channel(Channel c) {
    const PhysicalUnit physical = physical_unit(c);
    const auto unit = rate_unit(physical.name);  // deg/s or mm/s^2, both in the table (test RateUnit.*)
    return {"counts", unit->quantity, physical.per_count * unit->si_per_unit};
}

SampleUnit unit_of_name(const std::string& name) {
    if (const auto u = rate_unit(name)) return {u->name, u->quantity, u->si_per_unit};
    return {name, RateQuantity::unknown, 1.0};
}

}  // namespace driftlab::host::stats
