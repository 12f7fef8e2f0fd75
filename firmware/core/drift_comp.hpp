// DriftComp: the board's forward correction of eq. 1, eps(t) = C1 (1 - e^(-t/T)) + C2 with t since a cold start,
// in integer arithmetic and without exp(). Derivation and error bounds: docs/firmware.md "Drift compensation".
//
// The correction removes the turn-on transient and refers every output to the settled level:
//   out = value + C1 e^(-t/T) - offset,   offset = C1 + C2 - 512 counts for a channel calibrated to zero, else 0,
// so an uncalibrated-to-zero channel reads what it will read once warm (its static offset and gravity stay for the
// navigation's own calibration, as ArduPilot's INS_TCAL refers to a reference temperature), and a rate gyro calibrated
// to zero reads mid-scale at rest from power-on.
//
// e^(-t/T) is E on a grid of 2^16 ticks (0.262144 s): one step multiplies by a = e^(-h/T), kept as s = 1 - a in Q36
// (found once per calibration by a bit-serial division and a short series, to 30 significant bits); between grid points
// E is interpolated with the exponential's own curvature. Grid and E are functions of the tick only, so every port
// gives the same bytes.
#pragma once

#include <stdint.h>

#include "driftlab/channels.hpp"
#include "driftlab/proto/messages.hpp"

namespace driftlab {
namespace fw {

/// Ticks between two steps of the recursive exponential, as a power of two (the fraction within a step is then the
/// tick's low 16 bits).
constexpr uint8_t kCompStepShift = 16;
constexpr uint32_t kCompStepTicks = static_cast<uint32_t>(1) << kCompStepShift;

/// One channel's model as the board applies it.
struct ChannelModel {
  int32_t c1_q8;  ///< C1 [counts Q8]
  int32_t c2_q8;  ///< C2 [counts Q8]
  uint32_t t_ms;  ///< T [ms], proto::kCalTMinMs..kCalTMaxMs
  bool zero;      ///< refer the settled level to mid-scale (512 counts) as well
};

/// s = 1 - e^(-h/T) for the grid step h = kCompStepTicks, as mantissa / 2^shift with the mantissa near 2^30.
struct StepDecay {
  uint32_t mantissa;
  uint8_t shift;
};
/// Exposed for tests.
StepDecay step_decay(uint32_t t_ms);

/// One channel: E at the current grid point and the step's constants.
class ChannelDrift {
 public:
  ChannelDrift() : c1_q8_(0), offset_q8_(0), s_(), e_q32_(0), d_q32_(0), bend_q32_(0) {}

  /// Takes `model` at grid step `steps` since the cold start (E = a^steps), or, when `settled`, with E = 0 (a warm
  /// restart: the transient is taken as over).
  void load(const ChannelModel& model, uint32_t steps, bool settled);
  /// One grid step: E <- E a.
  void step();
  /// E at `fraction` [Q16] of the way to the next grid point [Q32]. Exposed for tests.
  uint32_t e_q32(uint16_t fraction) const;
  /// What the board adds to the channel's value at that point [counts Q8]: C1 E - offset, rounded half away from 0.
  int32_t correction_q8(uint16_t fraction) const;

 private:
  int32_t c1_q8_;
  int32_t offset_q8_;
  void prepare_step();

  StepDecay s_;
  uint32_t e_q32_;     // E at the grid point; 0xFFFFFFFF stands for 1
  uint32_t d_q32_;     // E s: what the next step takes off E
  uint32_t bend_q32_;  // d s/2 (about E x^2/2): the chord lies above the exponential by this times f (1 - f)
};

/// The four channels and the grid clock. The grid runs from tick 0 (the reset) whether or not a calibration is
/// loaded, so a calibration uploaded later starts at the right point of the exponential.
class DriftComp {
 public:
  DriftComp() : grid_tick_(0), steps_(0), active_(false), settled_(false) {}

  /// After a reset: `warm` = the reset kept the sensor powered (watchdog, external), so t since the cold start is
  /// unknown and the transient is taken as over.
  void reset(bool warm);
  /// Applies `models` (one per channel) from the current grid point on.
  void load(const ChannelModel (&models)[kChannelCount]);
  /// Outputs uncompensated from now on.
  void unload() { active_ = false; }
  /// Moves the grid up to `tick` (any conversion's tick; at most 2^31 ticks after the previous call).
  void advance_to(uint32_t tick);
  /// `value_q8` of `channel` corrected for its drift at `tick` (>= the grid point, < one step after).
  int32_t apply(Channel channel, int32_t value_q8, uint32_t tick) const;

  bool active() const { return active_; }
  bool settled() const { return settled_; }

 private:
  ChannelDrift channels_[kChannelCount];
  uint32_t grid_tick_;  // tick of the current grid point, wraps with the tick
  uint32_t steps_;      // grid points since the reset
  bool active_;
  bool settled_;
};

}  // namespace fw
}  // namespace driftlab
