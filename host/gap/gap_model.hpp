// The model the gap diagnosis simulates: the unit (front end, converter), the firmware's smoothing as recorded
// in the log, the calibrated base per channel (eq. 1 drift and white noise) and any effects added to it.
// docs/gap.md §Model.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "driftlab/channels.hpp"
#include "sim/model/drift.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::host::gap {

/// The firmware's least-squares smoothing and output timing (log metadata; docs/log-format.md).
struct Smoothing {
    double sample_period_s = 1.0;   ///< the rows' period, the spacing every lag and band counts [s]
    int conversions_per_output = 1; ///< conversions of each channel per output [-]
    int window = 1;                 ///< N of the sliding least-squares fit [conversions]
    int fit_order = 0;              ///< 0 = mean, 1 = line evaluated at the newest conversion
    /// Outputs the firmware made per row: 1 when every output is a row; more for polled rows that come slower than
    /// the outputs (a board paced faster than the recorder's clock, `hil --pty --speed 10` with `record --poll`).
    double outputs_per_row = 1.0;

    double output_period_s() const { return sample_period_s / outputs_per_row; }
    double conversion_period_s() const { return output_period_s() / conversions_per_output; }
};

/// The calibrated base of one channel.
struct ChannelBase {
    sim::DriftParams drift;          ///< eq. 1 [counts, s]
    double sigma_n_counts = 0.0;     ///< white noise before the quantiser [counts]
};

/// Gaussian processes of the model file that the diagnosis holds at the file's values on one channel (`gap --model`;
/// add_given_effects()): part of every spectrum fitted on the channel, never refitted. (They are simulated as
/// `effects` holds them.)
struct HeldNoise {
    struct Component {
        double variance_counts2 = 0.0;  ///< stationary variance [counts^2]
        double tau_s = 0.0;             ///< correlation time [s]
    };
    std::vector<Component> gauss_markov;  ///< Gauss-Markov components (flicker is a sum of them)
    double walk_counts2_per_s = 0.0;      ///< random walk: step variance per second [counts^2 / s]
};

/// Everything a replicate is simulated from.
struct GapModel {
    sim::SimModel unit;                              ///< front ends and converter (model file or the paper's)
    Smoothing smoothing;
    std::array<ChannelBase, kChannelCount> base{};
    std::vector<sim::EffectSpec> effects;            ///< the model file's effects, then those added (candidates)
    std::array<HeldNoise, kChannelCount> held{};     ///< the model file's Gaussian processes, per channel
};

/// Converter counts per physical unit of a channel [counts per deg/s or per g].
double counts_per_unit(const GapModel& model, Channel c);

}  // namespace driftlab::host::gap
