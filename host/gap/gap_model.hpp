// The model the gap diagnosis simulates: the unit (front end, converter), the firmware's smoothing as recorded
// in the log, the calibrated base per channel (eq. 1 drift and white noise) and any effects added to it.
// docs/gap.md §Model.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "driftlab/channels.hpp"
#include "sim/model/board_outputs.hpp"

namespace driftlab::host::gap {

using sim::ChannelBase;
using sim::Smoothing;

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

/// Everything a replicate is simulated from: the unit, its smoothing, calibrated base and effects (the model file's,
/// then those added as candidates), and what the diagnosis holds fixed.
struct GapModel : sim::OutputModel {
    std::array<HeldNoise, kChannelCount> held{};  ///< the model file's Gaussian processes, per channel
};

using sim::counts_per_unit;

}  // namespace driftlab::host::gap
