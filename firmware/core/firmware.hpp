// Firmware: the core's one stateful object. It owns the configuration, one LsWindow per channel, the saturation
// and loss bookkeeping, the frame decoder and the transmit sequence number, and reacts to exactly two events
// that the port's main loop delivers (hal.hpp). Architecture and timing: docs/firmware.md.
//
// Output cadence is counted in conversions, never read from a clock: in stream mode a SAMPLE (+ RAW in raw
// mode) follows every 4 x conversions_per_output-th conversion after arming (lost ones included), i.e. after
// the accel_z conversion that completes a round, stamped with that conversion's tick. So the same conversions
// give the same frames on every port and in every simulator. Each channel's value is its fit at its own newest
// conversion, so only accel_z's is at that tick; channel c's is (3 - c) conversion periods older. A POLL is
// answered in either mode with the windows as they are (in stream mode an extra SAMPLE off the grid, the
// cadence unchanged); with an empty window it reports n_window 0 and value 0 (docs/protocol.md §3.5, §3.6).
//
// A CONFIG_SET that changes the timing is applied at once (ACK, windows emptied) but re-arms the ADC at the
// next conversion of the old schedule, which it discards: the new grid starts one old period after that
// conversion's tick, a point both ports compute alike provided hal_init() runs at most one old period minus
// kMinArmWaitTicks (2) after it; later, arm_wait_ticks() starts the grid one new period after the call
// (docs/hal.md §1.1).
#pragma once

#include <stdint.h>

#include "driftlab/channels.hpp"
#include "driftlab/proto/decoder.hpp"
#include "firmware/core/commands.hpp"
#include "firmware/core/config.hpp"
#include "firmware/core/counter_store.hpp"
#include "firmware/core/drift_comp.hpp"
#include "firmware/core/key_store.hpp"
#include "firmware/core/ls_window.hpp"

namespace driftlab {
namespace fw {

class Firmware {
 public:
  Firmware();

  /// Main loop, once after the board's own set-up: reads the die temperature (hal_read_temperature(), so that every
  /// SAMPLE carries one), loads the command key, the replay counter and the calibration from EEPROM (a warm restart,
  /// per hal_reset_info(), takes the transient as over: drift_comp.hpp) and arms the default schedule (kDefaultConfig)
  /// via hal_init(), first trigger one period after hal_ticks().
  void start();

  /// Main loop: one finished conversion, in the order the ADC produced them. `code_counts` is 0..1023 and
  /// `tick` the trigger time [ticks] (hal.hpp Conversion); a tick gap of k periods means k - 1 lost conversions.
  void on_conversion(Channel channel, uint16_t code_counts, uint32_t tick);

  /// Main loop: one received UART byte. Complete valid frames are answered at once through hal_uart_write().
  void on_rx_byte(uint8_t byte);

  const Config& config() const { return config_; }
  /// Conversions lost since boot, saturating [conversions].
  uint16_t dropped() const { return dropped_; }
  const LsWindow& window(Channel channel) const { return windows_[channel_index(channel)]; }
  /// proto::CalState of the calibration in use.
  uint8_t cal_state() const { return cal_state_; }

 private:
  void apply(const Config& next);
  void arm(uint32_t first_trigger_tick);
  void note_output();
  void reset_windows();
  void load_calibration();
  void handle_frame();
  void act(const CommandOutcome& outcome);
  void note_refusal(uint8_t status);
  void take_key(const uint8_t* frame);
  void send_frame(const uint8_t* frame, uint8_t size);
  void send_sample();
  void send_raw();
  void send_version(bool legacy);
  void send_config();
  void send_status();
  void send_ack(const proto::AckPayload& ack);
  void send_nak(const proto::NakPayload& nak);
  void send_cal(const proto::CalPayload& cal);

  Config config_;
  LsWindow windows_[kChannelCount];
  uint16_t newest_code_counts_[kChannelCount];
  uint32_t newest_tick_;              // trigger tick of the newest conversion [ticks]
  uint32_t conversion_period_ticks_;  // of the armed schedule [ticks]
  bool have_conversion_;              // a conversion arrived since arming, so newest_tick_ anchors the gap check
  bool rearm_pending_;                // accepted new timing waits for the next conversion to anchor its grid
  uint16_t conversions_since_output_;
  uint16_t dropped_;
  uint16_t tx_overflow_bytes_;
  uint16_t tx_seq_;
  DriftComp comp_;
  uint8_t cal_state_;  // proto::CalState
  uint16_t cal_id_;    // of the calibration applied, 0 when none is
  KeyStore key_;
  CounterStore counter_;
  uint16_t auth_refused_;            // NAK unauthenticated sent, saturating
  uint16_t auth_replayed_;           // NAK replayed sent, saturating
  uint16_t temperature_code_;        // newest die temperature conversion, proto::kNoTemperature when none is current
  uint8_t outputs_per_temperature_;  // outputs between two temperature requests: about one a second
  uint8_t outputs_to_temperature_;   // outputs left until the next request
  proto::Decoder decoder_;
};

}  // namespace fw
}  // namespace driftlab
