// One channel's analog path: physical quantity -> transducer voltage -> amplifier -> converter input.
// The amplifier is described the way the paper describes it: it maps `center ± span` of the quantity onto the
// converter's 0..Vref (gyro ±90 °/s; accel ±1 g, the gravity axis 0..2 g). Quantities are °/s for the gyro
// and g for the accelerometer axes. docs/sim.md §Chain.
#pragma once

#include <array>

#include "driftlab/channels.hpp"

namespace driftlab::sim {

/// Unit of a channel's physical quantity, as spelled in key names: "dps" (°/s) or "g".
const char* channel_unit(Channel c);

/// Transducer and amplifier of one channel. Fields ending in _unit use the channel's unit (channel_unit()).
struct FrontEndParams {
    double sensitivity_v_per_unit = 1.0;  ///< transducer scale [V per °/s or V per g], > 0
    double null_v = 2.5;                  ///< transducer output at zero input [V]
    double span_unit = 1.0;               ///< half range mapped onto Vref/2 [°/s or g], > 0
    double center_unit = 0.0;             ///< input that reads mid-scale [°/s or g]
};

/// ENV-05S gyro and ADXL05 axes. Transducer scales are assumptions (no datasheet value was available;
/// docs/sim.md): they set only the voltage seen by analog-stage effects, never the overall counts per unit,
/// which follow from span alone (512/90 counts per °/s, 512 counts per g).
inline constexpr std::array<FrontEndParams, kChannelCount> kPaperFrontEnd = {{
    {0.0222, 2.5, 90.0, 0.0},
    {1.0, 2.5, 1.0, 0.0},
    {1.0, 2.5, 1.0, 0.0},
    {1.0, 2.5, 1.0, 1.0},
}};

/// The analog path of one channel for a converter of reference `vref_v`.
class FrontEnd {
public:
    FrontEnd(const FrontEndParams& params, double vref_v);

    /// Transducer output [V] for a physical input [°/s or g].
    double sensor_v(double quantity_unit) const {
        return params_.null_v + params_.sensitivity_v_per_unit * quantity_unit;
    }
    /// Amplifier output = converter input [V] for a transducer voltage [V].
    double amplifier_v(double sensor_v) const { return mid_v_ + gain_ * (sensor_v - center_sensor_v_); }

    double gain() const { return gain_; }  ///< amplifier gain [V/V]
    /// Converter counts per physical unit for an ideal converter with `levels` = 2^bits codes.
    double counts_per_unit(double levels) const { return levels / 2.0 / params_.span_unit; }
    const FrontEndParams& params() const { return params_; }

private:
    FrontEndParams params_;
    double mid_v_;
    double gain_;
    double center_sensor_v_;
};

}  // namespace driftlab::sim
