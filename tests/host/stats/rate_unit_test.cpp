// The shared table of rate units: each spelling's quantity and SI value against its definition, and the names a
// message lists.
#include "host/stats/rate_unit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "host/util/error.hpp"
#include "host/util/units.hpp"

namespace driftlab::host::stats {
namespace {

TEST(RateUnit, EachSpellingIsItsDefinitionInSI) {
    const double deg = 3.14159265358979323846 / 180.0;
    struct Case {
        const char* spelling;
        const char* name;
        RateQuantity quantity;
        double si;
    };
    for (const Case& c :
         {Case{"deg/s", "deg/s", RateQuantity::angular_rate, deg},
          Case{"dps", "deg/s", RateQuantity::angular_rate, deg},
          Case{"mdps", "mdps", RateQuantity::angular_rate, deg / 1000.0},
          Case{"deg/h", "deg/h", RateQuantity::angular_rate, deg / 3600.0},
          Case{"rad/s", "rad/s", RateQuantity::angular_rate, 1.0}, Case{"g", "g", RateQuantity::acceleration, 9.80665},
          Case{"mg", "mg", RateQuantity::acceleration, 9.80665e-3},
          Case{"m/s^2", "m/s^2", RateQuantity::acceleration, 1.0},
          Case{"m/s2", "m/s^2", RateQuantity::acceleration, 1.0},
          Case{"cm/s^2", "cm/s^2", RateQuantity::acceleration, 0.01},
          Case{"cm/s2", "cm/s^2", RateQuantity::acceleration, 0.01},
          Case{"mm/s^2", "mm/s^2", RateQuantity::acceleration, 0.001},
          Case{"mm/s2", "mm/s^2", RateQuantity::acceleration, 0.001}}) {
        const auto u = rate_unit(c.spelling);
        ASSERT_TRUE(u) << c.spelling;
        EXPECT_EQ(u->name, c.name) << c.spelling;
        EXPECT_EQ(u->quantity, c.quantity) << c.spelling;
        EXPECT_NEAR(u->si_per_unit / c.si, 1.0, 1e-15) << c.spelling;
    }
    for (const char* unknown : {"", "furlongs", "DEG/S", "m/s", "deg"}) EXPECT_FALSE(rate_unit(unknown)) << unknown;
}

// allan converts a log channel's terms to SI through the table, by the name of its physical unit.
TEST(RateUnit, EachChannelsPhysicalUnitIsInTheTable) {
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        const auto u = rate_unit(physical_unit(static_cast<Channel>(c)).name);
        ASSERT_TRUE(u) << kChannelNames[c];
        EXPECT_EQ(u->quantity, c == 0 ? RateQuantity::angular_rate : RateQuantity::acceleration) << kChannelNames[c];
    }
}

TEST(RateUnit, AMessageListsTheSpellingsOfOneQuantity) {
    EXPECT_EQ(rate_unit_names(RateQuantity::angular_rate), "deg/s, dps, mdps, deg/h, rad/s");
    EXPECT_EQ(rate_unit_names(RateQuantity::acceleration), "g, mg, m/s^2, m/s2, cm/s^2, cm/s2, mm/s^2, mm/s2");
    EXPECT_EQ(rate_unit_names(RateQuantity::unknown), "");
}

// Phase samples in an angle, a velocity or a time have their deviations in the rate's unit: deg -> deg/s (the
// table's entry, so its SI value), m/s -> m/s^2, ns -> ns/s (a clock's fractional frequency: no navigation quantity).
TEST(RateUnitOfPhase, EachPhaseUnitGivesItsRatesUnit) {
    const auto deg = rate_unit_of_phase("deg");
    ASSERT_TRUE(deg);
    EXPECT_EQ(deg->name, "deg/s");
    EXPECT_EQ(deg->quantity, RateQuantity::angular_rate);
    EXPECT_EQ(deg->si_per_unit, rate_unit("deg/s")->si_per_unit);
    EXPECT_EQ(rate_unit_of_phase("mdeg")->name, "mdps");
    EXPECT_EQ(rate_unit_of_phase("rad")->name, "rad/s");
    const auto velocity = rate_unit_of_phase("cm/s");
    ASSERT_TRUE(velocity);
    EXPECT_EQ(velocity->name, "cm/s^2");
    EXPECT_EQ(velocity->quantity, RateQuantity::acceleration);
    const auto ns = rate_unit_of_phase("ns");
    ASSERT_TRUE(ns);
    EXPECT_EQ(ns->name, "ns/s");
    EXPECT_EQ(ns->quantity, RateQuantity::unknown);
    for (const char* unknown : {"", "deg/s", "g", "sec", "DEG"}) EXPECT_FALSE(rate_unit_of_phase(unknown)) << unknown;
    EXPECT_EQ(phase_unit_names(), "angle: deg, mdeg, rad; velocity: m/s, cm/s, mm/s; time: s, ms, us, ns, ps");
}

TEST(UnitAssignment, PhaseSamplesTakeTheirIntegralsUnitAndHoldTheRates) {
    const UnitAssignment a = parse_unit_assignment({"gx:deg", "m/s"}, "--unit", InputKind::phase);
    EXPECT_EQ(a.for_column("gx")->name, "deg/s");
    EXPECT_EQ(a.for_column("ax")->name, "m/s^2");
    try {
        parse_unit_assignment({"gx:deg/s"}, "--unit", InputKind::phase);
        ADD_FAILURE() << "a rate's unit was taken for phase samples";
    } catch (const UsageError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("--unit 'gx:deg/s': unknown unit 'deg/s' for phase samples ('deg/s' is a "
                                              "rate's: give its integral's, e.g. deg for deg/s); angle: deg",
                                              0),
                  0u)
            << e.what();
    }
}

// report --unit: a column's own unit wins over the one for every column; a column without either has none.
TEST(UnitAssignment, AColumnsOwnUnitWinsOverTheOneForEveryColumn) {
    const UnitAssignment a = parse_unit_assignment({"gyro:deg/s", "mg", "ax:m/s2"}, "--unit");
    EXPECT_EQ(a.for_column("gyro")->name, "deg/s");
    EXPECT_EQ(a.for_column("ax")->name, "m/s^2");
    EXPECT_EQ(a.for_column("ay")->name, "mg");
    EXPECT_EQ(a.for_column("ay")->quantity, RateQuantity::acceleration);
    EXPECT_FALSE(parse_unit_assignment({"gyro:dps"}, "--unit").for_column("ay"));
    EXPECT_TRUE(parse_unit_assignment({}, "--unit").units.empty());
}

// Each refusal names the value as given; an unknown unit lists the ones the table knows.
TEST(UnitAssignment, BadValuesAreRefusedNamingThem) {
    const auto message = [](const std::vector<std::string>& values) {
        try {
            parse_unit_assignment(values, "--unit");
        } catch (const UsageError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message({"gyro:deg/sec"}),
              "--unit 'gyro:deg/sec': unknown unit 'deg/sec'; angular rate: deg/s, dps, mdps, deg/h, rad/s; "
              "acceleration: g, mg, m/s^2, m/s2, cm/s^2, cm/s2, mm/s^2, mm/s2");
    EXPECT_EQ(message({"gyro:"}).rfind("--unit 'gyro:': no unit; angular rate: deg/s", 0), 0u) << message({"gyro:"});
    EXPECT_EQ(message({":deg/s"}),
              "--unit ':deg/s': no column before ':' (COLUMN:UNIT, or UNIT alone for every column)");
    EXPECT_EQ(message({"gyro:deg/s", "gyro:rad/s"}),
              "--unit 'gyro:rad/s': column 'gyro' already has a unit (--unit 'gyro:deg/s')");
    EXPECT_EQ(message({"g", "mg"}), "--unit 'mg': every column already has a unit (--unit 'g')");
}

}  // namespace
}  // namespace driftlab::host::stats
