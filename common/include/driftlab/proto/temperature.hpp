// The ATmega328P's die temperature sensor (ADC8 against the internal 1.1 V reference) as SAMPLE's temp_code carries
// it (kNoTemperature: no reading), and the one conversion of a code to degrees Celsius (docs/protocol.md §3.6,
// docs/hardware.md). The transfer is the datasheet's typical one (table "Temperature vs. sensor output voltage": 242 mV
// at -45 °C, 314 mV at 25 °C, 380 mV at 85 °C), so an uncalibrated chip reads within ±10 °C of the truth; steps of one
// code are about 1 °C.
#pragma once

#include <stdint.h>

#include "driftlab/proto/messages.hpp"

namespace driftlab {
namespace proto {

/// The datasheet's typical sensor output [mV] at -45, 25 and 85 °C, joined by straight lines (and continued beyond the
/// ends along the outer ones), and the reference the sensor is converted against [mV].
constexpr double kTempSensorPointsC[3] = {-45.0, 25.0, 85.0};
constexpr double kTempSensorPointsMv[3] = {242.0, 314.0, 380.0};
constexpr double kTempReferenceMv = 1100.0;

/// The die temperature [°C] a code stands for: the middle of the code's step, code = V_in · 1024 / V_ref read
/// backwards, through the datasheet's points.
inline double celsius_of_temperature_code(uint16_t code) {
  const double mv = (static_cast<double>(code) + 0.5) * kTempReferenceMv / 1024.0;
  const int k = mv < kTempSensorPointsMv[1] ? 0 : 1;
  return kTempSensorPointsC[k] + (mv - kTempSensorPointsMv[k]) * (kTempSensorPointsC[k + 1] - kTempSensorPointsC[k]) /
                                     (kTempSensorPointsMv[k + 1] - kTempSensorPointsMv[k]);
}

/// The code the converter makes of a die at `celsius` [°C] (truncating, as the converter does), within 0..1023.
inline uint16_t temperature_code_of_celsius(double celsius) {
  const int k = celsius < kTempSensorPointsC[1] ? 0 : 1;
  const double mv = kTempSensorPointsMv[k] + (celsius - kTempSensorPointsC[k]) *
                                                 (kTempSensorPointsMv[k + 1] - kTempSensorPointsMv[k]) /
                                                 (kTempSensorPointsC[k + 1] - kTempSensorPointsC[k]);
  const double code = mv * 1024.0 / kTempReferenceMv;
  return code <= 0.0 ? 0 : code >= 1023.0 ? 1023 : static_cast<uint16_t>(code);
}

}  // namespace proto
}  // namespace driftlab
