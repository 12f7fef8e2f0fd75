// The bias processes among a model's effects (what `gap --model-out` writes as the effects it found), as the random
// walk each adds to a navigation axis's bias: the process noise the Allan terms of a short rest log cannot show.
// docs/nav.md §The filter.
#pragma once

#include <array>
#include <string>

#include "host/nav/unit_drift.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::host::nav {

struct EffectNoise {
    std::array<double, kNavAxes> bias_walk_psd{};  ///< added per axis [(rad/s)^2/s, (m/s^2)^2/s]
    std::string used;                              ///< "gauss_markov, flicker" or ""
};

/// Per axis: a Gauss-Markov bias of deviation sigma and correlation time tau walks as 2 sigma^2 / tau over times short
/// beside tau (its increments' variance); a rate random walk K as K^2; a flicker bias instability B as the walk that
/// reaches its plateau 0.664 B at 1 / (2 pi f_low), where its 1/f band ends. Other effects add nothing.
EffectNoise effect_noise(const sim::SimModel& unit);

}  // namespace driftlab::host::nav
