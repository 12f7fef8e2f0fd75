// Test support: random payload values of every protocol v1 type and field-by-field comparison.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "driftlab/proto/messages.hpp"

namespace driftlab {
namespace proto {
namespace testing {

template <typename T>
T random_int(std::mt19937& rng) {
  // Draw through uint32_t so every bit pattern of T, including negative ones, is reachable.
  return static_cast<T>(static_cast<typename std::make_unsigned<T>::type>(rng()));
}

inline void randomize(std::mt19937& rng, VersionPayload* p) {
  p->proto_version = random_int<uint8_t>(rng);
  p->fw_major = random_int<uint8_t>(rng);
  p->fw_minor = random_int<uint8_t>(rng);
  p->fw_patch = random_int<uint8_t>(rng);
  p->board_id = random_int<uint8_t>(rng);
  p->adc_bits = random_int<uint8_t>(rng);
  p->vref_mv = random_int<uint16_t>(rng);
  p->tick_hz = random_int<uint32_t>(rng);
  p->channel_count = random_int<uint8_t>(rng);
  for (auto& pin : p->adc_pin) {
    pin = random_int<uint8_t>(rng);
  }
  p->reset_cause = random_int<uint8_t>(rng);
  p->assert_line = random_int<uint16_t>(rng);
  p->cal_state = random_int<uint8_t>(rng);
  p->cal_id = random_int<uint16_t>(rng);
  p->auth_state = random_int<uint8_t>(rng);
  p->auth_counter = random_int<uint32_t>(rng);
}

inline void randomize(std::mt19937& rng, ConfigPayload* p) {
  p->output_period_ms = random_int<uint16_t>(rng);
  p->conversions_per_output = random_int<uint8_t>(rng);
  p->window = random_int<uint8_t>(rng);
  p->fit_order = random_int<uint8_t>(rng);
  p->mode = random_int<uint8_t>(rng);
  p->raw = random_int<uint8_t>(rng);
}

inline void randomize(std::mt19937& rng, SamplePayload* p) {
  p->tick = random_int<uint32_t>(rng);
  for (auto& v : p->value_q8) {
    v = random_int<int32_t>(rng);
  }
  p->sat_flags = random_int<uint8_t>(rng);
  p->n_window = random_int<uint8_t>(rng);
  p->dropped = random_int<uint16_t>(rng);
  p->cal_state = random_int<uint8_t>(rng);
  p->cal_id = random_int<uint16_t>(rng);
  p->temp_code = random_int<uint16_t>(rng);
}

inline void randomize(std::mt19937& rng, RawPayload* p) {
  p->tick = random_int<uint32_t>(rng);
  for (auto& c : p->code) {
    c = random_int<uint16_t>(rng);
  }
}

inline void randomize(std::mt19937& rng, AckPayload* p) {
  p->acked_type = random_int<uint8_t>(rng);
  p->acked_seq = random_int<uint16_t>(rng);
}

inline void randomize(std::mt19937& rng, NakPayload* p) {
  p->nacked_type = random_int<uint8_t>(rng);
  p->nacked_seq = random_int<uint16_t>(rng);
  p->status = random_int<uint8_t>(rng);
  p->field = random_int<uint8_t>(rng);
}

inline void randomize(std::mt19937& rng, StatusPayload* p) {
  p->uptime_ticks = random_int<uint32_t>(rng);
  p->rx_frames = random_int<uint16_t>(rng);
  p->rx_bad_crc = random_int<uint16_t>(rng);
  p->rx_bad_length = random_int<uint16_t>(rng);
  p->rx_unknown_type = random_int<uint16_t>(rng);
  p->rx_resync_bytes = random_int<uint16_t>(rng);
  p->rx_overflow = random_int<uint16_t>(rng);
  p->tx_overflow = random_int<uint16_t>(rng);
  p->dropped = random_int<uint16_t>(rng);
  p->cal_state = random_int<uint8_t>(rng);
  p->cal_id = random_int<uint16_t>(rng);
  p->auth_refused = random_int<uint16_t>(rng);
  p->auth_replayed = random_int<uint16_t>(rng);
}

inline void randomize(std::mt19937& rng, CalPayload* p) {
  p->cal_id = random_int<uint16_t>(rng);
  p->channel = random_int<uint8_t>(rng);
  p->flags = random_int<uint8_t>(rng);
  p->c1_q8 = random_int<int32_t>(rng);
  p->c2_q8 = random_int<int32_t>(rng);
  p->t_ms = random_int<uint32_t>(rng);
}

inline void randomize(std::mt19937& rng, CalGetPayload* p) { p->channel = random_int<uint8_t>(rng); }

inline void expect_fields_equal(const VersionPayload& a, const VersionPayload& b) {
  EXPECT_EQ(a.proto_version, b.proto_version);
  EXPECT_EQ(a.fw_major, b.fw_major);
  EXPECT_EQ(a.fw_minor, b.fw_minor);
  EXPECT_EQ(a.fw_patch, b.fw_patch);
  EXPECT_EQ(a.board_id, b.board_id);
  EXPECT_EQ(a.adc_bits, b.adc_bits);
  EXPECT_EQ(a.vref_mv, b.vref_mv);
  EXPECT_EQ(a.tick_hz, b.tick_hz);
  EXPECT_EQ(a.channel_count, b.channel_count);
  for (size_t c = 0; c < kChannelCount; ++c) {
    EXPECT_EQ(a.adc_pin[c], b.adc_pin[c]) << "adc_pin[" << c << "]";
  }
  EXPECT_EQ(a.reset_cause, b.reset_cause);
  EXPECT_EQ(a.assert_line, b.assert_line);
  EXPECT_EQ(a.cal_state, b.cal_state);
  EXPECT_EQ(a.cal_id, b.cal_id);
  EXPECT_EQ(a.auth_state, b.auth_state);
  EXPECT_EQ(a.auth_counter, b.auth_counter);
}

inline void expect_fields_equal(const ConfigPayload& a, const ConfigPayload& b) {
  EXPECT_EQ(a.output_period_ms, b.output_period_ms);
  EXPECT_EQ(a.conversions_per_output, b.conversions_per_output);
  EXPECT_EQ(a.window, b.window);
  EXPECT_EQ(a.fit_order, b.fit_order);
  EXPECT_EQ(a.mode, b.mode);
  EXPECT_EQ(a.raw, b.raw);
}

inline void expect_fields_equal(const SamplePayload& a, const SamplePayload& b) {
  EXPECT_EQ(a.tick, b.tick);
  for (size_t c = 0; c < kChannelCount; ++c) {
    EXPECT_EQ(a.value_q8[c], b.value_q8[c]) << "value_q8[" << c << "]";
  }
  EXPECT_EQ(a.sat_flags, b.sat_flags);
  EXPECT_EQ(a.n_window, b.n_window);
  EXPECT_EQ(a.dropped, b.dropped);
  EXPECT_EQ(a.cal_state, b.cal_state);
  EXPECT_EQ(a.cal_id, b.cal_id);
  EXPECT_EQ(a.temp_code, b.temp_code);
}

inline void expect_fields_equal(const RawPayload& a, const RawPayload& b) {
  EXPECT_EQ(a.tick, b.tick);
  for (size_t c = 0; c < kChannelCount; ++c) {
    EXPECT_EQ(a.code[c], b.code[c]) << "code[" << c << "]";
  }
}

inline void expect_fields_equal(const AckPayload& a, const AckPayload& b) {
  EXPECT_EQ(a.acked_type, b.acked_type);
  EXPECT_EQ(a.acked_seq, b.acked_seq);
}

inline void expect_fields_equal(const NakPayload& a, const NakPayload& b) {
  EXPECT_EQ(a.nacked_type, b.nacked_type);
  EXPECT_EQ(a.nacked_seq, b.nacked_seq);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.field, b.field);
}

inline void expect_fields_equal(const StatusPayload& a, const StatusPayload& b) {
  EXPECT_EQ(a.uptime_ticks, b.uptime_ticks);
  EXPECT_EQ(a.rx_frames, b.rx_frames);
  EXPECT_EQ(a.rx_bad_crc, b.rx_bad_crc);
  EXPECT_EQ(a.rx_bad_length, b.rx_bad_length);
  EXPECT_EQ(a.rx_unknown_type, b.rx_unknown_type);
  EXPECT_EQ(a.rx_resync_bytes, b.rx_resync_bytes);
  EXPECT_EQ(a.rx_overflow, b.rx_overflow);
  EXPECT_EQ(a.tx_overflow, b.tx_overflow);
  EXPECT_EQ(a.dropped, b.dropped);
  EXPECT_EQ(a.cal_state, b.cal_state);
  EXPECT_EQ(a.cal_id, b.cal_id);
  EXPECT_EQ(a.auth_refused, b.auth_refused);
  EXPECT_EQ(a.auth_replayed, b.auth_replayed);
}

inline void expect_fields_equal(const CalPayload& a, const CalPayload& b) {
  EXPECT_EQ(a.cal_id, b.cal_id);
  EXPECT_EQ(a.channel, b.channel);
  EXPECT_EQ(a.flags, b.flags);
  EXPECT_EQ(a.c1_q8, b.c1_q8);
  EXPECT_EQ(a.c2_q8, b.c2_q8);
  EXPECT_EQ(a.t_ms, b.t_ms);
}

inline void expect_fields_equal(const CalGetPayload& a, const CalGetPayload& b) { EXPECT_EQ(a.channel, b.channel); }

}  // namespace testing
}  // namespace proto
}  // namespace driftlab
