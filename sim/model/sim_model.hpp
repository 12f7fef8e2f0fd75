// SimModel: everything a model file describes (converter, per-channel analog path, drift and noise, effects,
// firmware settings, link), with the paper's unit as the default. model_file.hpp reads and writes it.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "driftlab/channels.hpp"
#include "driftlab/proto/messages.hpp"
#include "sim/link/link_params.hpp"
#include "sim/model/adc.hpp"
#include "sim/model/drift.hpp"
#include "sim/model/sensor.hpp"

namespace driftlab::sim {

/// One channel of the base model. Fields ending in _unit use the channel's unit (°/s or g, channel_unit()).
struct ChannelModel {
    FrontEndParams front_end;
    double input_unit = 0.0;          ///< constant true input (sensor at rest: 0, or 1 g on the vertical axis)
    DriftParams drift;                ///< eq. 1, the at-rest reading [counts]
    double raw_noise_std_unit = 0.0;  ///< standard deviation of the raw codes at rest [°/s or g]
};

/// An effect as named in the model file, with its TOML table (parsed and checked by the effect registry).
struct EffectSpec {
    std::string name;
    toml::table table;
};

/// The whole simulated unit.
struct SimModel {
    std::string name = "paper";
    AdcParams adc;
    std::array<ChannelModel, kChannelCount> channels;
    std::vector<EffectSpec> effects;
    proto::ConfigPayload firmware{};  ///< CONFIG the host sends at start (docs/protocol.md §3.4)
    LinkParams link;
};

/// The paper's unit: Table 1 drift, raw noise 0.187 °/s (gyro) and 0.0141 g (each accel axis), ±90 °/s and
/// ±1 g spans (accel_z 0..2 g, reading 1 g at rest), 5 V reference, a lossless 9600-baud link, 1 s polling.
SimModel paper_model();

}  // namespace driftlab::sim
