// Die temperature in virtual time (die_temperature.hpp).
#include "sim/hil/die_temperature.hpp"

#include <algorithm>
#include <cmath>

#include "driftlab/proto/temperature.hpp"

namespace driftlab::sim {

double DieTemperature::celsius(double t_s) const {
    return settled_c - (settled_c - start_c) * std::exp(-std::max(t_s, 0.0) / tau_s);
}

std::uint16_t DieTemperature::code(double t_s) const { return proto::temperature_code_of_celsius(celsius(t_s)); }

}  // namespace driftlab::sim
