// The paper's two experiments as presets of a host-in-the-loop run (docs/sim.md §Presets).
//  fig3: 4000 s from power-on, with the model's own firmware settings (paper.toml: one output a second, mean
//        of 25 conversions per output): the warm-up drift of Fig. 3 and Table 1.
//  fig2: 1000 outputs 0.1 s apart from a sensor powered an hour earlier (settled, so the spread is noise, not
//        warm-up), raw and least-squares values side by side: window 17, fit order 0, which takes the gyro's raw
//        0.187 deg/s down by sqrt(17) = 4.12 to 0.0454 deg/s (paper: 0.045).
#pragma once

#include <optional>
#include <string_view>

#include "sim/hil/hil.hpp"

namespace driftlab::sim {

enum class Preset : std::uint8_t { fig3, fig2 };

/// "fig3" or "fig2"; nothing for any other name.
std::optional<Preset> preset_from_name(std::string_view name);

/// Sets duration, warm-up and the firmware CONFIG fields the preset fixes, over `options.model`.
void apply_preset(Preset preset, HilOptions& options);

/// Only the run's duration and warm-up (what apply_preset sets besides the firmware).
void apply_preset_run(Preset preset, HilOptions& options);

/// Only the firmware CONFIG fields the preset fixes (those apply_preset sets), over `fw`.
void apply_preset_firmware(Preset preset, proto::ConfigPayload& fw);

/// Least-squares window of the fig2 preset [conversions].
inline constexpr std::uint8_t kFig2Window = 17;

}  // namespace driftlab::sim
