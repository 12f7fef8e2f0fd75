// The synthetic sensor: for one conversion of one channel at a nominal instant it returns the code the
// converter produces. Chain (docs/sim.md §Chain, sim/effects/effect.hpp):
//   true input [°/s, g] -> physical effects -> transducer -> amplifier -> analog effects [V]
//   -> counts = V/LSB + (eps(t) - mid-scale) + white noise -> converter effects -> round, clip -> code,
// where eps(t) is eq. 1 (the at-rest reading) and timing effects move the instant first.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "sim/effects/effect.hpp"
#include "sim/model/adc.hpp"
#include "sim/model/drift.hpp"
#include "sim/model/sensor.hpp"
#include "sim/model/sim_model.hpp"
#include "sim/model/white_noise.hpp"

namespace driftlab::sim {

/// One conversion's result.
struct Conversion {
    std::uint16_t code;  ///< converter output [counts]
    double t_s;          ///< actual instant after timing effects [s since power-on]
};

class SensorModel {
public:
    /// Builds the chain for `model` with every random component seeded from `seed` (own substreams). The sensor
    /// was powered `powered_before_boot_s` before the board's clock started (`--warm`).
    SensorModel(const SimModel& model, std::uint64_t seed, double powered_before_boot_s = 0.0);

    /// Converts channel `c` at nominal instant `board_t_s` of the board's clock [s since its start]. Timing
    /// effects move that instant by the board's clock error, which runs from the board's start, not the sensor's
    /// power-on; eq. 1 and the other effects then see the sensor's time. A channel's instant never goes before its
    /// previous one. Throws std::logic_error when an effect makes the converter input NaN.
    Conversion convert(Channel c, double board_t_s);

    /// Analog noise sigma of a channel [counts], as calibrated from its raw standard deviation.
    double analog_sigma_counts(Channel c) const { return noise_[channel_index(c)].sigma_counts(); }
    /// Converter counts per physical unit of a channel [counts per °/s or per g].
    double counts_per_unit(Channel c) const;
    const Adc& adc() const { return adc_; }

private:
    Adc adc_;
    double powered_before_boot_s_;
    double mid_counts_;
    std::vector<FrontEnd> front_ends_;
    std::vector<Drift> drifts_;
    std::vector<WhiteNoise> noise_;
    ChannelValues inputs_unit_{};
    std::array<std::vector<std::unique_ptr<Effect>>, 4> by_stage_;  // indexed by Stage
    const Effect* temperature_ = nullptr;  // the first effect that models the unit's temperature, when there is one
    std::array<double, kChannelCount> last_t_s_{};
    std::array<bool, kChannelCount> started_{};
};

}  // namespace driftlab::sim
