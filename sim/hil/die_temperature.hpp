// The microcontroller's die temperature in virtual time, which the board's ADC8 reads (docs/sim.md "Die
// temperature"): the room at power-on, warming by its own dissipation towards a settled temperature, as ArduPilot's
// SITL models an IMU's, T(t) = settled - (settled - start) e^(-t/tau). Native and AVR targets read the same code at
// the same instant.
#pragma once

#include <cstdint>

namespace driftlab::sim {

struct DieTemperature {
    double start_c = 25.0;    ///< at power-on [°C]
    double settled_c = 28.0;  ///< once the board's own heating has settled [°C]
    double tau_s = 300.0;     ///< time constant of the warming [s]

    /// The die's temperature `t_s` seconds after power-on [°C].
    double celsius(double t_s) const;
    /// The code the sensor gives then (proto::temperature_code_of_celsius: the datasheet's typical transfer).
    std::uint16_t code(double t_s) const;
};

}  // namespace driftlab::sim
