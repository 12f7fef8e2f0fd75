// The board's die temperature in virtual time (die_temperature.hpp): SITL's exponential warming, T(t) = settled -
// (settled - start) e^(-t/tau), and the sensor's code of it.
#include "sim/hil/die_temperature.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "driftlab/proto/temperature.hpp"

namespace driftlab::sim {
namespace {

TEST(DieTemperature, WarmsExponentiallyFromTheRoomToItsSettledTemperature) {
    const DieTemperature die{20.0, 32.0, 200.0};
    EXPECT_DOUBLE_EQ(die.celsius(0.0), 20.0);
    EXPECT_NEAR(die.celsius(200.0), 32.0 - 12.0 / std::exp(1.0), 1e-12);
    EXPECT_NEAR(die.celsius(1e5), 32.0, 1e-9);
    EXPECT_EQ(die.code(0.0), proto::temperature_code_of_celsius(20.0));
    EXPECT_EQ(die.code(1e5), proto::temperature_code_of_celsius(32.0));
}

TEST(DieTemperature, TheDefaultIsARoomAt25CWarmingThreeDegreesInFiveMinutes) {
    const DieTemperature die;
    EXPECT_EQ(die.code(0.0), 292);
    EXPECT_NEAR(die.celsius(300.0), 28.0 - 3.0 / std::exp(1.0), 1e-12);
}

}  // namespace
}  // namespace driftlab::sim
