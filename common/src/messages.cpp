// Payload layouts of protocol v2 (messages.hpp; docs/protocol.md §3): fields in declaration order, little-endian,
// no padding. Each pair below is the single place where that layout is written down in code.
#include "driftlab/proto/messages.hpp"

#include "driftlab/proto/byte_order.hpp"

namespace driftlab {
namespace proto {

size_t serialize(const VersionPayload& p, uint8_t* out, size_t out_size) {
  if (out_size < kVersionPayloadSize) {
    return 0;
  }
  out[0] = p.proto_version;
  out[1] = p.fw_major;
  out[2] = p.fw_minor;
  out[3] = p.fw_patch;
  out[4] = p.board_id;
  out[5] = p.adc_bits;
  put_u16_le(out + 6, p.vref_mv);
  put_u32_le(out + 8, p.tick_hz);
  out[12] = p.channel_count;
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    out[13 + c] = p.adc_pin[c];
  }
  out[17] = p.reset_cause;
  put_u16_le(out + 18, p.assert_line);
  out[20] = p.cal_state;
  put_u16_le(out + 21, p.cal_id);
  out[23] = p.auth_state;
  put_u32_le(out + 24, p.auth_counter);
  return kVersionPayloadSize;
}

bool parse(const uint8_t* in, size_t in_size, VersionPayload* out) {
  if (in_size != kVersionPayloadSize) {
    return false;
  }
  out->proto_version = in[0];
  out->fw_major = in[1];
  out->fw_minor = in[2];
  out->fw_patch = in[3];
  out->board_id = in[4];
  out->adc_bits = in[5];
  out->vref_mv = get_u16_le(in + 6);
  out->tick_hz = get_u32_le(in + 8);
  out->channel_count = in[12];
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    out->adc_pin[c] = in[13 + c];
  }
  out->reset_cause = in[17];
  out->assert_line = get_u16_le(in + 18);
  out->cal_state = in[20];
  out->cal_id = get_u16_le(in + 21);
  out->auth_state = in[23];
  out->auth_counter = get_u32_le(in + 24);
  return true;
}

size_t serialize(const ConfigPayload& p, uint8_t* out, size_t out_size) {
  if (out_size < kConfigPayloadSize) {
    return 0;
  }
  put_u16_le(out, p.output_period_ms);
  out[2] = p.conversions_per_output;
  out[3] = p.window;
  out[4] = p.fit_order;
  out[5] = p.mode;
  out[6] = p.raw;
  return kConfigPayloadSize;
}

bool parse(const uint8_t* in, size_t in_size, ConfigPayload* out) {
  if (in_size != kConfigPayloadSize) {
    return false;
  }
  out->output_period_ms = get_u16_le(in);
  out->conversions_per_output = in[2];
  out->window = in[3];
  out->fit_order = in[4];
  out->mode = in[5];
  out->raw = in[6];
  return true;
}

size_t serialize(const SamplePayload& p, uint8_t* out, size_t out_size) {
  if (out_size < kSamplePayloadSize) {
    return 0;
  }
  put_u32_le(out, p.tick);
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    put_i32_le(out + 4 + 4 * c, p.value_q8[c]);
  }
  out[20] = p.sat_flags;
  out[21] = p.n_window;
  put_u16_le(out + 22, p.dropped);
  out[24] = p.cal_state;
  put_u16_le(out + 25, p.cal_id);
  put_u16_le(out + 27, p.temp_code);
  return kSamplePayloadSize;
}

bool parse(const uint8_t* in, size_t in_size, SamplePayload* out) {
  if (in_size != kSamplePayloadSize) {
    return false;
  }
  out->tick = get_u32_le(in);
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    out->value_q8[c] = get_i32_le(in + 4 + 4 * c);
  }
  out->sat_flags = in[20];
  out->n_window = in[21];
  out->dropped = get_u16_le(in + 22);
  out->cal_state = in[24];
  out->cal_id = get_u16_le(in + 25);
  out->temp_code = get_u16_le(in + 27);
  return true;
}

size_t serialize(const RawPayload& p, uint8_t* out, size_t out_size) {
  if (out_size < kRawPayloadSize) {
    return 0;
  }
  put_u32_le(out, p.tick);
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    put_u16_le(out + 4 + 2 * c, p.code[c]);
  }
  return kRawPayloadSize;
}

bool parse(const uint8_t* in, size_t in_size, RawPayload* out) {
  if (in_size != kRawPayloadSize) {
    return false;
  }
  out->tick = get_u32_le(in);
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    out->code[c] = get_u16_le(in + 4 + 2 * c);
  }
  return true;
}

size_t serialize(const AckPayload& p, uint8_t* out, size_t out_size) {
  if (out_size < kAckPayloadSize) {
    return 0;
  }
  out[0] = p.acked_type;
  put_u16_le(out + 1, p.acked_seq);
  return kAckPayloadSize;
}

bool parse(const uint8_t* in, size_t in_size, AckPayload* out) {
  if (in_size != kAckPayloadSize) {
    return false;
  }
  out->acked_type = in[0];
  out->acked_seq = get_u16_le(in + 1);
  return true;
}

size_t serialize(const NakPayload& p, uint8_t* out, size_t out_size) {
  if (out_size < kNakPayloadSize) {
    return 0;
  }
  out[0] = p.nacked_type;
  put_u16_le(out + 1, p.nacked_seq);
  out[3] = p.status;
  out[4] = p.field;
  return kNakPayloadSize;
}

bool parse(const uint8_t* in, size_t in_size, NakPayload* out) {
  if (in_size != kNakPayloadSize) {
    return false;
  }
  out->nacked_type = in[0];
  out->nacked_seq = get_u16_le(in + 1);
  out->status = in[3];
  out->field = in[4];
  return true;
}

size_t serialize(const StatusPayload& p, uint8_t* out, size_t out_size) {
  if (out_size < kStatusPayloadSize) {
    return 0;
  }
  put_u32_le(out, p.uptime_ticks);
  put_u16_le(out + 4, p.rx_frames);
  put_u16_le(out + 6, p.rx_bad_crc);
  put_u16_le(out + 8, p.rx_bad_length);
  put_u16_le(out + 10, p.rx_unknown_type);
  put_u16_le(out + 12, p.rx_resync_bytes);
  put_u16_le(out + 14, p.rx_overflow);
  put_u16_le(out + 16, p.tx_overflow);
  put_u16_le(out + 18, p.dropped);
  out[20] = p.cal_state;
  put_u16_le(out + 21, p.cal_id);
  put_u16_le(out + 23, p.auth_refused);
  put_u16_le(out + 25, p.auth_replayed);
  return kStatusPayloadSize;
}

bool parse(const uint8_t* in, size_t in_size, StatusPayload* out) {
  if (in_size != kStatusPayloadSize) {
    return false;
  }
  out->uptime_ticks = get_u32_le(in);
  out->rx_frames = get_u16_le(in + 4);
  out->rx_bad_crc = get_u16_le(in + 6);
  out->rx_bad_length = get_u16_le(in + 8);
  out->rx_unknown_type = get_u16_le(in + 10);
  out->rx_resync_bytes = get_u16_le(in + 12);
  out->rx_overflow = get_u16_le(in + 14);
  out->tx_overflow = get_u16_le(in + 16);
  out->dropped = get_u16_le(in + 18);
  out->cal_state = in[20];
  out->cal_id = get_u16_le(in + 21);
  out->auth_refused = get_u16_le(in + 23);
  out->auth_replayed = get_u16_le(in + 25);
  return true;
}

size_t serialize(const CalPayload& p, uint8_t* out, size_t out_size) {
  if (out_size < kCalPayloadSize) {
    return 0;
  }
  put_u16_le(out, p.cal_id);
  out[2] = p.channel;
  out[3] = p.flags;
  put_i32_le(out + 4, p.c1_q8);
  put_i32_le(out + 8, p.c2_q8);
  put_u32_le(out + 12, p.t_ms);
  return kCalPayloadSize;
}

bool parse(const uint8_t* in, size_t in_size, CalPayload* out) {
  if (in_size != kCalPayloadSize) {
    return false;
  }
  out->cal_id = get_u16_le(in);
  out->channel = in[2];
  out->flags = in[3];
  out->c1_q8 = get_i32_le(in + 4);
  out->c2_q8 = get_i32_le(in + 8);
  out->t_ms = get_u32_le(in + 12);
  return true;
}

size_t serialize(const CalGetPayload& p, uint8_t* out, size_t out_size) {
  if (out_size < kCalGetPayloadSize) {
    return 0;
  }
  out[0] = p.channel;
  return kCalGetPayloadSize;
}

bool parse(const uint8_t* in, size_t in_size, CalGetPayload* out) {
  if (in_size != kCalGetPayloadSize) {
    return false;
  }
  out->channel = in[0];
  return true;
}

const char* config_field_name(uint8_t field) {
  static const char* const kNames[] = {
      "output_period_ms", "conversions_per_output", "window", "fit_order", "mode", "raw"};
  return field < sizeof kNames / sizeof kNames[0] ? kNames[field] : nullptr;
}

const char* cal_state_name(uint8_t state) {
  static const char* const kNames[] = {"none", "active", "settled", "damaged", "mixed"};
  return state < sizeof kNames / sizeof kNames[0] ? kNames[state] : nullptr;
}

const char* cal_field_name(uint8_t field) {
  static const char* const kNames[] = {"cal_id", "channel", "flags", "c1_q8", "c2_q8", "t_ms"};
  return field < sizeof kNames / sizeof kNames[0] ? kNames[field] : nullptr;
}

}  // namespace proto
}  // namespace driftlab
