// The synthetic sensor: for one conversion of one channel at a nominal instant it returns the code the
// converter produces. Chain (docs/sim.md §Chain, sim/effects/effect.hpp):
//   true input [°/s, g] -> physical effects -> transducer -> amplifier -> analog effects [V]
//   -> counts = V/LSB + (eps(t) - mid-scale) + white noise -> converter effects -> round, clip -> code,
// where eps(t) is eq. 1 (the at-rest reading) and timing effects move the instant first.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "sim/effects/effect.hpp"
#include "sim/model/adc.hpp"
#include "sim/model/drift.hpp"
#include "sim/model/sensor.hpp"
#include "sim/model/sim_model.hpp"
#include "sim/model/white_noise.hpp"

namespace driftlab::sim {

/// One channel's base in the chain: eq. 1 and the white noise before the quantiser.
struct ChannelBase {
    DriftParams drift;            ///< eq. 1 [counts, s]
    double sigma_n_counts = 0.0;  ///< analog white noise before the quantiser [counts]
};
using ChannelBases = std::array<ChannelBase, kChannelCount>;

/// The base a model file states: each channel's eq. 1, and the analog sigma whose quantised codes have the file's
/// raw standard deviation (white_noise.hpp).
ChannelBases base_of(const SimModel& model);

/// A converter that replaces the model's converter effects and quantiser: the code of a converter input [counts].
using Quantiser = std::function<int(double input_counts)>;

/// What a caller adds to one conversion beyond the model: gap-eval's truth signals and converters, and the eq. 1
/// values that many replicates of one model share (board_outputs.hpp).
struct ConversionExtras {
    double added_counts = 0.0;             ///< added at the converter input [counts]
    const double* drift_counts = nullptr;  ///< eq. 1 less mid-scale at this instant [counts]; null: evaluated here
    const Quantiser* quantiser = nullptr;  ///< replaces converter effects and quantiser; null: the model's
};

/// One conversion's result.
struct Conversion {
    std::uint16_t code;  ///< converter output [counts]
    double t_s;          ///< actual instant after timing effects [s since power-on]
};

/// The one sensor chain: `hil` (native and AVR), the pseudo-terminal board and the gap's replicates all convert
/// through it, so a model and a seed give one set of codes whichever of them asks.
class SensorModel {
public:
    /// Builds the chain for `model` with every random component seeded from `seed` (own substreams). The sensor
    /// was powered `powered_before_boot_s` before the board's clock started (`--warm`).
    SensorModel(const SimModel& model, std::uint64_t seed, double powered_before_boot_s = 0.0);
    /// The chain of `unit`'s front ends and converter with each channel's base and the effects given instead of
    /// the unit's own (a model calibrated to a log, host/gap).
    SensorModel(const SimModel& unit, const ChannelBases& base, const std::vector<EffectSpec>& effects,
                std::uint64_t seed, double powered_before_boot_s = 0.0);

    /// Converts channel `c` at nominal instant `board_t_s` of the board's clock [s since its start]. Timing
    /// effects move that instant by the board's clock error, which runs from the board's start, not the sensor's
    /// power-on; eq. 1 and the other effects then see the sensor's time. A channel's instant never goes before its
    /// previous one. Throws std::logic_error when an effect makes the converter input NaN.
    Conversion convert(Channel c, double board_t_s, const ConversionExtras& extras = {});

    /// The unit's motion: what each channel's true input gains over the model's at-rest input (gyro [deg/s], accel
    /// [g]) at an instant of the board's clock [s since its start]. Empty (the default): the unit at rest.
    using MotionSource = std::function<ChannelValues(double board_t_s)>;
    void set_motion(MotionSource motion) { motion_ = std::move(motion); }

    /// Analog noise sigma of a channel [counts].
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
    MotionSource motion_;
    std::array<std::vector<std::unique_ptr<Effect>>, 4> by_stage_;  // indexed by Stage
    const Effect* temperature_ = nullptr;  // the first effect that models the unit's temperature, when there is one
    std::array<double, kChannelCount> last_t_s_{};
    std::array<bool, kChannelCount> started_{};
};

}  // namespace driftlab::sim
