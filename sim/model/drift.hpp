// Turn-on drift of a channel's at-rest reading, the paper's eq. 1: eps(t) = C1 (1 - exp(-t/T)) + C2, in A/D
// counts, t in seconds since the sensor was powered. Defaults are Table 1 of the paper; docs/sim.md §3.
#pragma once

#include <array>

#include "driftlab/channels.hpp"

namespace driftlab::sim {

/// Parameters of eq. 1 for one channel.
struct DriftParams {
    double c1_counts = 0.0;    ///< rise from power-on to settled [counts]
    double c2_counts = 512.0;  ///< reading at power-on [counts]
    double tau_s = 1.0;        ///< time constant T [s], > 0
};

/// Table 1 of the paper, in Channel order (gyro, accel_x, accel_y, accel_z).
inline constexpr std::array<DriftParams, kChannelCount> kPaperDrift = {{
    {3.0, 505.0, 411.0},
    {2.0, 470.0, 953.0},
    {23.0, 474.0, 937.0},
    {28.0, 622.0, 1050.0},
}};

/// eps(t) of eq. 1 [counts] at `t_s` seconds after power-on.
class Drift {
public:
    explicit Drift(const DriftParams& params) : params_(params) {}

    double at_counts(double t_s) const;

    const DriftParams& params() const { return params_; }

private:
    DriftParams params_;
};

}  // namespace driftlab::sim
