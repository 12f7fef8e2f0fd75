// Firmware: event handling, output cadence and replies (firmware.hpp; docs/firmware.md, docs/protocol.md §3).
#include "firmware/core/firmware.hpp"

#include "driftlab/proto/command_auth.hpp"
#include "driftlab/proto/encoder.hpp"
#include "driftlab/proto/messages.hpp"
#include "driftlab/proto/wire.hpp"
#include "firmware/core/cal_store.hpp"
#include "firmware/core/hal.hpp"
#include "firmware/core/version.hpp"

namespace driftlab {
namespace fw {
namespace {

uint16_t saturate_u16(uint32_t value) {
  return value > 0xFFFFU ? static_cast<uint16_t>(0xFFFFU) : static_cast<uint16_t>(value);
}

uint16_t add_saturating(uint16_t a, uint32_t b) { return saturate_u16(static_cast<uint32_t>(a) + b); }

bool timing_differs(const Config& a, const Config& b) {
  return a.output_period_ms != b.output_period_ms || a.conversions_per_output != b.conversions_per_output;
}

}  // namespace

Firmware::Firmware()
    : config_(kDefaultConfig),
      windows_(),
      newest_code_counts_(),
      newest_tick_(0),
      conversion_period_ticks_(0),
      have_conversion_(false),
      rearm_pending_(false),
      conversions_since_output_(0),
      dropped_(0),
      tx_overflow_bytes_(0),
      tx_seq_(0),
      comp_(),
      cal_state_(static_cast<uint8_t>(proto::CalState::none)),
      cal_id_(0),
      key_(),
      counter_(),
      auth_refused_(0),
      auth_replayed_(0),
      temperature_code_(proto::kNoTemperature),
      outputs_per_temperature_(1),
      outputs_to_temperature_(0),
      decoder_() {
  reset_windows();
}

void Firmware::start() {
  // The die temperature at power-on, while the ADC is idle; the grid is counted from before it, so a port whose
  // reading takes time arms the same grid as one whose reading takes none.
  const uint32_t now = hal_ticks();
  temperature_code_ = hal_read_temperature();
  arm(now + conversion_period_ticks(config_.output_period_ms, config_.conversions_per_output));
  // After arming: reading the calibration takes the AVR a millisecond or two, which must not move the grid. A reset
  // that kept the sensor powered leaves t since its cold start unknown (drift_comp.hpp).
  const uint8_t cause = hal_reset_info().cause;
  const bool warm = (cause & (kResetPowerOn | kResetBrownOut)) == 0 && (cause & (kResetExternal | kResetWatchdog)) != 0;
  comp_.reset(warm);
  load_calibration();
  key_.load();
  counter_.load();
}

void Firmware::arm(uint32_t first_trigger_tick) {
  const AdcSchedule schedule = adc_schedule(config_, first_trigger_tick);
  conversion_period_ticks_ = schedule.conversion_period_ticks;
  rearm_pending_ = false;
  have_conversion_ = false;
  conversions_since_output_ = 0;
  // About one temperature a second, the first at the first output; a schedule without room for one reports none
  // rather than an old one.
  outputs_per_temperature_ =
      static_cast<uint8_t>(config_.output_period_ms >= 1000U ? 1U : 1000U / config_.output_period_ms);
  outputs_to_temperature_ = 0;
  if (conversion_period_ticks_ < kMinTemperaturePeriodTicks) {
    temperature_code_ = proto::kNoTemperature;
  }
  hal_init(schedule);
}

void Firmware::note_output() {
  if (conversion_period_ticks_ < kMinTemperaturePeriodTicks) {
    return;
  }
  if (outputs_to_temperature_ > 0) {
    --outputs_to_temperature_;
    return;
  }
  hal_request_temperature();
  outputs_to_temperature_ = static_cast<uint8_t>(outputs_per_temperature_ - 1U);
}

void Firmware::reset_windows() {
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    windows_[c].reset(config_.window);
  }
}

void Firmware::load_calibration() {
  const StoredCal stored = read_calibration();
  cal_id_ = stored.cal_id;
  if (stored.state != proto::CalState::active) {
    comp_.unload();
    cal_state_ = static_cast<uint8_t>(stored.state);
    return;
  }
  comp_.load(stored.models);
  cal_state_ = static_cast<uint8_t>(comp_.settled() ? proto::CalState::settled : proto::CalState::active);
}

void Firmware::apply(const Config& next) {
  const bool retime = timing_differs(config_, next);
  const bool rewindow = retime || config_.window != next.window;
  config_ = next;
  if (rewindow) {
    reset_windows();
  }
  if (retime) {
    rearm_pending_ = true;
  }
}

void Firmware::on_conversion(Channel channel, uint16_t code_counts, uint32_t tick) {
  if (channel == kTemperatureInput) {
    // Between two conversions of the round, not one of them: no window, no gap, no output (hal.hpp).
    temperature_code_ = code_counts;
    return;
  }
  DRIFTLAB_ASSERT(code_counts <= LsWindow::kMaxCode && channel_index(channel) < kChannelCount);
  comp_.advance_to(tick);
  if (rearm_pending_) {
    // The last conversion of the old schedule anchors the new one (firmware.hpp); its code is not used.
    arm(tick + conversion_period_ticks_);
    return;
  }
  uint32_t elapsed_conversions = 1;
  if (have_conversion_) {
    // Trigger ticks sit on the period grid, so the gap in whole periods (rounded, tolerant of a port that stamps
    // a little late) counts the conversions lost in between. The usual gap of one period skips the division,
    // which costs the AVR some 600 cycles.
    const uint32_t gap_ticks = tick - newest_tick_;
    if (gap_ticks != conversion_period_ticks_) {
      const uint32_t gap_periods = (gap_ticks + conversion_period_ticks_ / 2U) / conversion_period_ticks_;
      if (gap_periods > 1U) {
        elapsed_conversions = gap_periods;
        dropped_ = add_saturating(dropped_, gap_periods - 1U);
      }
    }
  }
  have_conversion_ = true;
  newest_tick_ = tick;

  const uint8_t c = channel_index(channel);
  newest_code_counts_[c] = code_counts;
  windows_[c].push(code_counts);

  const uint32_t per_output = static_cast<uint32_t>(kChannelCount) * config_.conversions_per_output;
  uint32_t since = conversions_since_output_ + elapsed_conversions;
  if (since >= per_output) {
    since -= per_output;
    if (since >= per_output) {
      since %= per_output;  // only after a long loss
    }
    note_output();
    if (config_.mode == proto::OutputMode::stream) {
      send_sample();
    }
  }
  conversions_since_output_ = static_cast<uint16_t>(since);
}

void Firmware::on_rx_byte(uint8_t byte) {
  if (!decoder_.feed(byte)) {
    return;
  }
  do {
    handle_frame();
  } while (decoder_.next());
}

void Firmware::handle_frame() {
  if (decoder_.version() == proto::kLegacyProtocolVersion) {
    // A version-1 host's HELLO: VERSION in v1's layout and framing, whose proto_version 2 that host refuses by
    // number (docs/protocol.md §1.1).
    send_version(true);
    return;
  }
  const uint8_t* frame = decoder_.frame();
  const proto::Status auth = check_auth(frame, AuthView{key_.state(), &key_.key(), counter_.value()});
  const CommandOutcome outcome =
      decide(decoder_.type_id(), decoder_.seq(), decoder_.payload(), decoder_.payload_len(), config_.mode, auth);
  const bool changes_board =
      outcome.reply == Reply::ack || outcome.reply == Reply::cal_ack || outcome.reply == Reply::key_ack;
  if (changes_board && key_.state() == proto::AuthState::keyed) {
    // Kept before the command acts, so a reset in between cannot admit it twice (counter_store.hpp).
    counter_.advance_to(proto::trailer_counter(frame));
  }
  if (outcome.reply == Reply::key_ack) {
    take_key(frame);
  }
  act(outcome);
}

void Firmware::act(const CommandOutcome& outcome) {
  switch (outcome.reply) {
  case Reply::version: send_version(false); break;
  case Reply::config: send_config(); break;
  case Reply::sample: send_sample(); break;
  case Reply::status: send_status(); break;
  case Reply::ack:
    apply(outcome.config);
    send_ack(outcome.ack);
    break;
  case Reply::nak:
    note_refusal(outcome.nak.status);
    send_nak(outcome.nak);
    break;
  case Reply::cal_ack:
    store_entry(outcome.cal);
    load_calibration();
    send_ack(outcome.ack);
    break;
  case Reply::key_ack: send_ack(outcome.ack); break;
  case Reply::cal: {
    proto::CalPayload entry = {};
    if (read_entry(outcome.cal.channel, &entry) == RecordState::valid) {
      send_cal(entry);
    } else {
      send_nak(outcome.nak);
    }
    break;
  }
  }
}

void Firmware::note_refusal(uint8_t status) {
  if (status == static_cast<uint8_t>(proto::Status::unauthenticated)) {
    auth_refused_ = add_saturating(auth_refused_, 1);
  } else if (status == static_cast<uint8_t>(proto::Status::replayed)) {
    auth_replayed_ = add_saturating(auth_replayed_, 1);
  }
}

void Firmware::take_key(const uint8_t* frame) {
  proto::Key next = {};
  proto::seal_key(key_.key(), counter_.value(), frame + proto::kOffsetPayload, next);
  key_.store(next);
}

void Firmware::send_frame(const uint8_t* frame, uint8_t size) {
  // Every frame takes a sequence number, sent or not, so the host sees a lost frame as a jump.
  ++tx_seq_;
  if (size == 0) {
    return;
  }
  if (hal_uart_write(frame, size) != size) {
    tx_overflow_bytes_ = add_saturating(tx_overflow_bytes_, size);
  }
}

void Firmware::send_sample() {
  proto::SamplePayload p = {};
  p.tick = newest_tick_;
  uint8_t n_window = LsWindow::kMaxWindow;
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    // An empty window's 0 is no reading (n_window 0 says so) and stays 0.
    const int32_t estimate_q8 = windows_[c].estimate_q8(config_.fit_order);
    p.value_q8[c] = windows_[c].n() == 0 ? 0 : comp_.apply(static_cast<Channel>(c), estimate_q8, newest_tick_);
    if (windows_[c].saturated()) {
      p.sat_flags = static_cast<uint8_t>(p.sat_flags | (1U << c));
    }
    // Between outputs the channels' fill levels differ by one during warm-up; report the least filled.
    n_window = windows_[c].n() < n_window ? windows_[c].n() : n_window;
  }
  p.n_window = n_window;
  p.dropped = dropped_;
  p.cal_state = cal_state_;
  p.cal_id = cal_id_;
  p.temp_code = temperature_code_;
  uint8_t frame[proto::kMaxFrameSize];
  send_frame(frame, static_cast<uint8_t>(proto::encode_sample(p, tx_seq_, frame, sizeof frame)));
  if (config_.raw) {
    send_raw();
  }
}

void Firmware::send_raw() {
  proto::RawPayload p = {};
  p.tick = newest_tick_;
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    p.code[c] = newest_code_counts_[c];
  }
  uint8_t frame[proto::kMaxFrameSize];
  send_frame(frame, static_cast<uint8_t>(proto::encode_raw(p, tx_seq_, frame, sizeof frame)));
}

void Firmware::send_version(bool legacy) {
  const ResetInfo reset = hal_reset_info();
  proto::VersionPayload p = {};
  p.proto_version = proto::kProtocolVersion;
  p.fw_major = kFwMajor;
  p.fw_minor = kFwMinor;
  p.fw_patch = kFwPatch;
  p.board_id = kBoardId;
  p.adc_bits = kAdcBits;
  p.vref_mv = kVrefMv;
  p.tick_hz = kTickHz;
  p.channel_count = kChannelCount;
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    p.adc_pin[c] = kAdcPin[c];
  }
  p.reset_cause = reset.cause;
  p.assert_line = reset.assert_line;
  p.cal_state = cal_state_;
  p.cal_id = cal_id_;
  p.auth_state = static_cast<uint8_t>(key_.state());
  p.auth_counter = counter_.value();
  uint8_t frame[proto::kMaxFrameSize];
  send_frame(frame, static_cast<uint8_t>(legacy ? proto::encode_legacy_version(p, tx_seq_, frame, sizeof frame)
                                                : proto::encode_version(p, tx_seq_, frame, sizeof frame)));
}

void Firmware::send_config() {
  uint8_t frame[proto::kMaxFrameSize];
  send_frame(frame,
             static_cast<uint8_t>(proto::encode_config(config_to_payload(config_), tx_seq_, frame, sizeof frame)));
}

void Firmware::send_status() {
  const proto::DecoderCounters& rx = decoder_.counters();
  proto::StatusPayload p = {};
  p.uptime_ticks = hal_ticks();
  p.rx_frames = saturate_u16(rx.frames_ok);
  p.rx_bad_crc = saturate_u16(rx.bad_crc);
  p.rx_bad_length = saturate_u16(rx.bad_length);
  p.rx_unknown_type = saturate_u16(rx.unknown_type);
  p.rx_resync_bytes = saturate_u16(rx.resync_bytes);
  p.rx_overflow = hal_rx_overflow_count();
  p.tx_overflow = tx_overflow_bytes_;
  p.dropped = dropped_;
  p.cal_state = cal_state_;
  p.cal_id = cal_id_;
  p.auth_refused = auth_refused_;
  p.auth_replayed = auth_replayed_;
  uint8_t frame[proto::kMaxFrameSize];
  send_frame(frame, static_cast<uint8_t>(proto::encode_status(p, tx_seq_, frame, sizeof frame)));
}

void Firmware::send_ack(const proto::AckPayload& ack) {
  uint8_t frame[proto::kMaxFrameSize];
  send_frame(frame, static_cast<uint8_t>(proto::encode_ack(ack, tx_seq_, frame, sizeof frame)));
}

void Firmware::send_nak(const proto::NakPayload& nak) {
  uint8_t frame[proto::kMaxFrameSize];
  send_frame(frame, static_cast<uint8_t>(proto::encode_nak(nak, tx_seq_, frame, sizeof frame)));
}

void Firmware::send_cal(const proto::CalPayload& cal) {
  uint8_t frame[proto::kMaxFrameSize];
  send_frame(frame, static_cast<uint8_t>(proto::encode_cal(cal, tx_seq_, frame, sizeof frame)));
}

}  // namespace fw
}  // namespace driftlab
