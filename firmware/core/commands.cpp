// Commands: validation order and replies as documented in commands.hpp (docs/protocol.md §3-§4).
#include "firmware/core/commands.hpp"

#include "driftlab/proto/msg_table.hpp"
#include "driftlab/proto/wire.hpp"
#include "firmware/core/cal_store.hpp"

namespace driftlab {
namespace fw {
namespace {

CommandOutcome nak(uint8_t type_id, uint16_t seq, proto::Status status, uint8_t field) {
  CommandOutcome out = {};
  out.reply = Reply::nak;
  out.nak = proto::NakPayload{type_id, seq, static_cast<uint8_t>(status), field};
  return out;
}

CommandOutcome reply(Reply r) {
  CommandOutcome out = {};
  out.reply = r;
  return out;
}

CommandOutcome decide_config_set(uint8_t type_id, uint16_t seq, const uint8_t* payload, uint8_t payload_len) {
  proto::ConfigPayload wire = {};
  if (!proto::parse(payload, static_cast<uint8_t>(payload_len - proto::kAuthTrailerBytes), &wire)) {
    return nak(type_id, seq, proto::Status::bad_length, proto::kNakFieldNone);
  }
  const ConfigCheck check = validate(wire);
  if (check.status != proto::Status::ok) {
    return nak(type_id, seq, check.status, check.field);
  }
  CommandOutcome out = {};
  out.reply = Reply::ack;
  out.config = config_from_payload(wire);
  out.ack = proto::AckPayload{type_id, seq};
  return out;
}

CommandOutcome decide_cal_set(uint8_t type_id, uint16_t seq, const uint8_t* payload, uint8_t payload_len) {
  CommandOutcome out = {};
  if (!proto::parse(payload, static_cast<uint8_t>(payload_len - proto::kAuthTrailerBytes), &out.cal)) {
    return nak(type_id, seq, proto::Status::bad_length, proto::kNakFieldNone);
  }
  const CalCheck check = validate(out.cal);
  if (check.status != proto::Status::ok) {
    return nak(type_id, seq, check.status, check.field);
  }
  out.reply = Reply::cal_ack;
  out.ack = proto::AckPayload{type_id, seq};
  return out;
}

CommandOutcome decide_cal_get(uint8_t type_id, uint16_t seq, const uint8_t* payload, uint8_t payload_len) {
  proto::CalGetPayload wire = {};
  if (!proto::parse(payload, payload_len, &wire)) {
    return nak(type_id, seq, proto::Status::bad_length, proto::kNakFieldNone);
  }
  if (wire.channel >= kChannelCount) {
    return nak(type_id, seq, proto::Status::out_of_range, 0);
  }
  CommandOutcome out = reply(Reply::cal);
  out.cal.channel = wire.channel;
  out.nak = proto::NakPayload{type_id, seq, static_cast<uint8_t>(proto::Status::not_stored), proto::kNakFieldNone};
  return out;
}

CommandOutcome ack(Reply r, uint8_t type_id, uint16_t seq) {
  CommandOutcome out = reply(r);
  out.ack = proto::AckPayload{type_id, seq};
  return out;
}

}  // namespace

proto::Status check_auth(const uint8_t* frame, const AuthView& auth) {
  const uint8_t type_id = frame[proto::kOffsetType];
  proto::MsgSpec spec = {};
  if (!proto::is_authenticated(type_id) || !proto::find_spec(type_id, &spec) ||
      frame[proto::kOffsetLen] != spec.payload_len) {
    return proto::Status::ok;
  }
  switch (auth.state) {
  case proto::AuthState::open:
    return type_id == proto::type_id(proto::MsgType::key_set) ? proto::Status::not_allowed : proto::Status::ok;
  case proto::AuthState::keyed:
    if (!proto::trailer_tag_matches(frame, *auth.key)) {
      return proto::Status::unauthenticated;
    }
    return proto::trailer_counter(frame) > auth.counter ? proto::Status::ok : proto::Status::replayed;
  case proto::AuthState::damaged: break;
  }
  return proto::Status::unauthenticated;
}

CommandOutcome decide(uint8_t type_id, uint16_t seq, const uint8_t* payload, uint8_t payload_len,
                      proto::OutputMode mode, proto::Status auth) {
  proto::MsgSpec spec = {};
  if (!proto::find_spec(type_id, &spec)) {
    return nak(type_id, seq, proto::Status::unknown_type, proto::kNakFieldNone);
  }
  if (spec.direction != proto::Direction::host_to_fw) {
    return nak(type_id, seq, proto::Status::not_allowed, proto::kNakFieldNone);
  }
  if (payload_len != spec.payload_len) {
    return nak(type_id, seq, proto::Status::bad_length, proto::kNakFieldNone);
  }
  if (auth != proto::Status::ok) {
    return nak(type_id, seq, auth, proto::kNakFieldNone);
  }
  switch (static_cast<proto::MsgType>(type_id)) {
  case proto::MsgType::hello: return reply(Reply::version);
  case proto::MsgType::config_get: return reply(Reply::config);
  case proto::MsgType::config_set: return decide_config_set(type_id, seq, payload, payload_len);
  case proto::MsgType::poll:
    // A streaming board answers on its output grid only: an extra SAMPLE would make the log's spacing irregular.
    if (mode == proto::OutputMode::stream) {
      return nak(type_id, seq, proto::Status::not_allowed, proto::kNakFieldNone);
    }
    return reply(Reply::sample);
  case proto::MsgType::status_get: return reply(Reply::status);
  case proto::MsgType::cal_set: return decide_cal_set(type_id, seq, payload, payload_len);
  case proto::MsgType::cal_get: return decide_cal_get(type_id, seq, payload, payload_len);
  case proto::MsgType::key_set: return ack(Reply::key_ack, type_id, seq);
  default:
    // Every host-to-firmware type is listed above; a new one in the table must be added here.
    return nak(type_id, seq, proto::Status::unknown_type, proto::kNakFieldNone);
  }
}

}  // namespace fw
}  // namespace driftlab
