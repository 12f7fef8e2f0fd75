// Transducer and amplifier; see sensor.hpp.
#include "sim/model/sensor.hpp"

namespace driftlab::sim {

const char* channel_unit(Channel c) { return c == Channel::gyro ? "dps" : "g"; }

FrontEnd::FrontEnd(const FrontEndParams& params, double vref_v)
    : params_(params),
      mid_v_(vref_v / 2.0),
      gain_(vref_v / 2.0 / (params.sensitivity_v_per_unit * params.span_unit)),
      center_sensor_v_(params.null_v + params.sensitivity_v_per_unit * params.center_unit) {}

}  // namespace driftlab::sim
