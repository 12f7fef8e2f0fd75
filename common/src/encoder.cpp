// Frame encoder (encoder.hpp; docs/protocol.md §1-§2). Typed encoders serialize straight into the caller's buffer
// behind the header, so no second payload copy is made.
#include "driftlab/proto/encoder.hpp"

#include "driftlab/proto/byte_order.hpp"
#include "driftlab/proto/crc16.hpp"
#include "driftlab/proto/wire.hpp"

namespace driftlab {
namespace proto {
namespace {

void put_header(uint8_t type, uint16_t seq, uint8_t payload_len, uint8_t* out, uint8_t version) {
  out[kOffsetSync0] = kSync0;
  out[kOffsetSync1] = kSync1;
  out[kOffsetVersion] = version;
  out[kOffsetType] = type;
  put_u16_le(out + kOffsetSeq, seq);
  out[kOffsetLen] = payload_len;
}

size_t put_crc(uint8_t crc_seed, uint8_t payload_len, uint8_t* out) {
  const size_t crc_offset = kOffsetPayload + payload_len;
  uint16_t crc = crc16_ibm3740(out + kCrcStart, crc_offset - kCrcStart);
  crc = crc16_ibm3740_update(crc, crc_seed);
  put_u16_le(out + crc_offset, crc);
  return frame_size(payload_len);
}

// Writes header and CRC around a payload already at out + kOffsetPayload; the caller checked type and sizes.
size_t finish_frame(uint8_t type, uint8_t crc_seed, uint16_t seq, uint8_t payload_len, uint8_t* out,
                    uint8_t version = kProtocolVersion) {
  put_header(type, seq, payload_len, out, version);
  return put_crc(crc_seed, payload_len, out);
}

// As finish_frame for an authenticated type, whose fields are at out + kOffsetPayload: the trailer goes in between.
size_t finish_command(uint8_t type, const MsgSpec& spec, uint16_t seq, const CommandAuth& auth, uint8_t* out) {
  put_header(type, seq, spec.payload_len, out, kProtocolVersion);
  write_trailer(out, auth);
  return put_crc(spec.crc_seed, spec.payload_len, out);
}

// Common checks of the typed encoders: known type, and room for the whole frame.
bool room_for(MsgType type, size_t out_size, MsgSpec* spec) {
  return find_spec(type_id(type), spec) && out_size >= frame_size(spec->payload_len);
}

template <typename Payload>
size_t encode_typed(MsgType type, const Payload& p, uint16_t seq, uint8_t* out, size_t out_size) {
  MsgSpec spec{};
  if (!room_for(type, out_size, &spec)) {
    return 0;
  }
  if (serialize(p, out + kOffsetPayload, out_size - kOffsetPayload) != spec.payload_len) {
    return 0;
  }
  return finish_frame(type_id(type), spec.crc_seed, seq, spec.payload_len, out);
}

template <typename Fields>
size_t encode_command(MsgType type, const Fields& p, const CommandAuth& auth, uint16_t seq, uint8_t* out,
                      size_t out_size) {
  MsgSpec spec{};
  if (!room_for(type, out_size, &spec)) {
    return 0;
  }
  const size_t fields = static_cast<size_t>(spec.payload_len - kAuthTrailerBytes);
  if (serialize(p, out + kOffsetPayload, fields) != fields) {
    return 0;
  }
  return finish_command(type_id(type), spec, seq, auth, out);
}

size_t encode_empty(MsgType type, uint16_t seq, uint8_t* out, size_t out_size) {
  MsgSpec spec{};
  if (!room_for(type, out_size, &spec) || spec.payload_len != 0) {
    return 0;
  }
  return finish_frame(type_id(type), spec.crc_seed, seq, 0, out);
}

}  // namespace

size_t encode_frame(uint8_t type, uint16_t seq, const uint8_t* payload, size_t payload_len, uint8_t* out,
                    size_t out_size) {
  MsgSpec spec{};
  if (is_authenticated(type) || !find_spec(type, &spec) || payload_len != spec.payload_len ||
      out_size < frame_size(payload_len)) {
    return 0;
  }
  for (size_t i = 0; i < payload_len; ++i) {
    out[kOffsetPayload + i] = payload[i];
  }
  return finish_frame(type, spec.crc_seed, seq, spec.payload_len, out);
}

size_t encode_authenticated(uint8_t type, uint16_t seq, const uint8_t* fields, size_t fields_len,
                            const CommandAuth& auth, uint8_t* out, size_t out_size) {
  MsgSpec spec{};
  if (!is_authenticated(type) || !find_spec(type, &spec) || fields_len + kAuthTrailerBytes != spec.payload_len ||
      out_size < frame_size(spec.payload_len)) {
    return 0;
  }
  for (size_t i = 0; i < fields_len; ++i) {
    out[kOffsetPayload + i] = fields[i];
  }
  return finish_command(type, spec, seq, auth, out);
}

size_t encode_hello(uint16_t seq, uint8_t* out, size_t out_size) {
  return encode_empty(MsgType::hello, seq, out, out_size);
}

size_t encode_version(const VersionPayload& p, uint16_t seq, uint8_t* out, size_t out_size) {
  return encode_typed(MsgType::version, p, seq, out, out_size);
}

size_t encode_config_get(uint16_t seq, uint8_t* out, size_t out_size) {
  return encode_empty(MsgType::config_get, seq, out, out_size);
}

size_t encode_config_set(const ConfigPayload& p, const CommandAuth& auth, uint16_t seq, uint8_t* out, size_t out_size) {
  return encode_command(MsgType::config_set, p, auth, seq, out, out_size);
}

size_t encode_config(const ConfigPayload& p, uint16_t seq, uint8_t* out, size_t out_size) {
  return encode_typed(MsgType::config, p, seq, out, out_size);
}

size_t encode_poll(uint16_t seq, uint8_t* out, size_t out_size) {
  return encode_empty(MsgType::poll, seq, out, out_size);
}

size_t encode_sample(const SamplePayload& p, uint16_t seq, uint8_t* out, size_t out_size) {
  return encode_typed(MsgType::sample, p, seq, out, out_size);
}

size_t encode_raw(const RawPayload& p, uint16_t seq, uint8_t* out, size_t out_size) {
  return encode_typed(MsgType::raw, p, seq, out, out_size);
}

size_t encode_ack(const AckPayload& p, uint16_t seq, uint8_t* out, size_t out_size) {
  return encode_typed(MsgType::ack, p, seq, out, out_size);
}

size_t encode_nak(const NakPayload& p, uint16_t seq, uint8_t* out, size_t out_size) {
  return encode_typed(MsgType::nak, p, seq, out, out_size);
}

size_t encode_status_get(uint16_t seq, uint8_t* out, size_t out_size) {
  return encode_empty(MsgType::status_get, seq, out, out_size);
}

size_t encode_status(const StatusPayload& p, uint16_t seq, uint8_t* out, size_t out_size) {
  return encode_typed(MsgType::status, p, seq, out, out_size);
}

size_t encode_cal_set(const CalPayload& p, const CommandAuth& auth, uint16_t seq, uint8_t* out, size_t out_size) {
  return encode_command(MsgType::cal_set, p, auth, seq, out, out_size);
}

size_t encode_key_set(const Key& new_key, const CommandAuth& auth, uint16_t seq, uint8_t* out, size_t out_size) {
  uint8_t sealed[kKeySetFieldBytes];
  if (auth.key == nullptr) {
    return 0;
  }
  seal_key(*auth.key, auth.counter, new_key, sealed);
  return encode_authenticated(type_id(MsgType::key_set), seq, sealed, sizeof sealed, auth, out, out_size);
}

size_t encode_cal_get(const CalGetPayload& p, uint16_t seq, uint8_t* out, size_t out_size) {
  return encode_typed(MsgType::cal_get, p, seq, out, out_size);
}

size_t encode_cal(const CalPayload& p, uint16_t seq, uint8_t* out, size_t out_size) {
  return encode_typed(MsgType::cal, p, seq, out, out_size);
}

size_t encode_legacy_hello(uint16_t seq, uint8_t* out, size_t out_size) {
  if (out_size < frame_size(0)) {
    return 0;
  }
  return finish_frame(type_id(MsgType::hello), kLegacyHelloSeed, seq, 0, out, kLegacyProtocolVersion);
}

size_t encode_legacy_version(const VersionPayload& p, uint16_t seq, uint8_t* out, size_t out_size) {
  // Version 2 appended its fields, so v1's payload is the first kLegacyVersionPayloadSize bytes of v2's.
  if (out_size < frame_size(kVersionPayloadSize) ||
      serialize(p, out + kOffsetPayload, out_size - kOffsetPayload) != kVersionPayloadSize) {
    return 0;
  }
  return finish_frame(type_id(MsgType::version), kLegacyVersionSeed, seq, kLegacyVersionPayloadSize, out,
                      kLegacyProtocolVersion);
}

}  // namespace proto
}  // namespace driftlab
