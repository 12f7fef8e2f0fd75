// The diagnosis's final model as a model file (`driftlab gap --model-out`): the unit it was given, the calibrated
// eq. 1 and white noise of each analysed channel, the firmware's smoothing as the log recorded it, and the effects
// it added, so that `driftlab hil --model` simulates the unit the log came from. docs/gap.md §Model file out.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "host/gap/gap_model.hpp"

namespace driftlab::host::gap {

struct ModelOut {
    sim::SimModel model;
    std::vector<std::string> notes;  ///< what the model file could not hold exactly (a channel's noise below its floor)
};

/// The firmware CONFIG that smooths as `smoothing` does (poll mode; RAW frames when `raw`). Throws DataError naming
/// `source` where no CONFIG the firmware accepts does (a period that is no whole millisecond, a window beyond 64).
proto::ConfigPayload firmware_config(const Smoothing& smoothing, bool raw, const std::string& source);

/// `model` as a simulator model. `channels`: the analysed channels (the others keep the unit's drift and noise);
/// `raw`: the log carried raw codes (the firmware then sends them). Throws as firmware_config().
ModelOut model_out(const GapModel& model, const std::array<bool, kChannelCount>& channels, bool raw,
                   const std::string& source);

}  // namespace driftlab::host::gap
