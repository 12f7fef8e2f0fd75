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
    double sample_period_s = 1.0;   ///< output period [s]
    int conversions_per_output = 1; ///< conversions of each channel per output [-]
    int window = 1;                 ///< N of the sliding least-squares fit [conversions]
    int fit_order = 0;              ///< 0 = mean, 1 = line evaluated at the newest conversion
};

/// The calibrated base of one channel.
struct ChannelBase {
    sim::DriftParams drift;          ///< eq. 1 [counts, s]
    double sigma_n_counts = 0.0;     ///< white noise before the quantiser [counts]
};

/// Everything a replicate is simulated from.
struct GapModel {
    sim::SimModel unit;                              ///< front ends and converter (model file or the paper's)
    Smoothing smoothing;
    std::array<ChannelBase, kChannelCount> base{};
    std::vector<sim::EffectSpec> effects;            ///< effects added to the base (candidates)
};

/// Converter counts per physical unit of a channel [counts per deg/s or per g].
double counts_per_unit(const GapModel& model, Channel c);

}  // namespace driftlab::host::gap
