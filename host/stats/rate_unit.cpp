// Rate units by name; see rate_unit.hpp.
#include "host/stats/rate_unit.hpp"

#include <array>
#include <numbers>

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

}  // namespace

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

}  // namespace driftlab::host::stats
