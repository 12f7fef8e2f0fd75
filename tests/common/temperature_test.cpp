// The die temperature transfer (temperature.hpp) against the datasheet's typical table: 242 mV at -45 °C, 314 mV at
// 25 °C, 380 mV at 85 °C, converted as code = V · 1024 / 1.1 V.
#include "driftlab/proto/temperature.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace driftlab {
namespace proto {
namespace {

TEST(Temperature, TheDatasheetPointsGiveTheirCodes) {
  EXPECT_EQ(temperature_code_of_celsius(-45.0), 225);  // 242 mV -> 225.3
  EXPECT_EQ(temperature_code_of_celsius(25.0), 292);   // 314 mV -> 292.3
  EXPECT_EQ(temperature_code_of_celsius(85.0), 353);   // 380 mV -> 353.7
  EXPECT_EQ(temperature_code_of_celsius(-400.0), 0);
  EXPECT_EQ(temperature_code_of_celsius(2000.0), 1023);
}

TEST(Temperature, ACodeReadsBackWithinItsStepOfTheTemperatureThatMadeIt) {
  const double step_c = kTempReferenceMv / 1024.0 / ((314.0 - 242.0) / 70.0);  // the flatter segment's, 1.04 °C
  for (double c = -40.0; c <= 85.0; c += 0.37) {
    const double back = celsius_of_temperature_code(temperature_code_of_celsius(c));
    EXPECT_LE(std::fabs(back - c), step_c / 2.0 + 1e-9) << c;
  }
}

}  // namespace
}  // namespace proto
}  // namespace driftlab
