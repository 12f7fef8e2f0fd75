// CalStore: entries, CRCs and the state of the set (cal_store.hpp).
#include "firmware/core/cal_store.hpp"

#include "firmware/core/hal.hpp"

namespace driftlab {
namespace fw {
namespace {

CalCheck reject(proto::CalField field) { return CalCheck{proto::Status::out_of_range, static_cast<uint8_t>(field)}; }

bool within(int32_t value_q8) { return value_q8 >= -proto::kCalCountsMaxQ8 && value_q8 <= proto::kCalCountsMaxQ8; }

}  // namespace

CalCheck validate(const proto::CalPayload& payload) {
  if (payload.channel >= kChannelCount) {
    return reject(proto::CalField::channel);
  }
  if ((payload.flags & static_cast<uint8_t>(~proto::kCalFlagZero)) != 0) {
    return reject(proto::CalField::flags);
  }
  if (payload.cal_id != 0) {
    if (!within(payload.c1_q8)) {
      return reject(proto::CalField::c1_q8);
    }
    if (!within(payload.c2_q8)) {
      return reject(proto::CalField::c2_q8);
    }
    if (payload.t_ms < proto::kCalTMinMs || payload.t_ms > proto::kCalTMaxMs) {
      return reject(proto::CalField::t_ms);
    }
  }
  return CalCheck{proto::Status::ok, proto::kNakFieldNone};
}

void store_entry(const proto::CalPayload& payload) {
  uint8_t entry[kCalEntryBytes];
  entry_bytes(payload, entry);
  hal_eeprom_write(entry_address(payload.channel), entry, kCalEntryBytes);
}

RecordState read_entry(uint8_t channel, proto::CalPayload* out) {
  uint8_t entry[kCalEntryBytes];
  hal_eeprom_read(entry_address(channel), entry, kCalEntryBytes);
  const RecordState state = record_state(entry, proto::kCalPayloadSize);
  if (state != RecordState::valid) {
    return state;
  }
  if (!proto::parse(entry, proto::kCalPayloadSize, out) || out->channel != channel ||
      validate(*out).status != proto::Status::ok) {
    return RecordState::damaged;
  }
  return RecordState::valid;
}

StoredCal read_calibration() {
  StoredCal out = {};
  uint8_t unset = 0;
  uint16_t first_id = 0;
  bool ids_differ = false;
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    proto::CalPayload entry = {};
    const RecordState read = read_entry(c, &entry);
    if (read == RecordState::damaged) {
      out.state = proto::CalState::damaged;
      return out;
    }
    if (read == RecordState::erased || entry.cal_id == 0) {
      ++unset;
      continue;
    }
    ids_differ = ids_differ || (first_id != 0 && entry.cal_id != first_id);
    first_id = entry.cal_id;
    out.models[c] = ChannelModel{entry.c1_q8, entry.c2_q8, entry.t_ms, (entry.flags & proto::kCalFlagZero) != 0};
  }
  if (unset == kChannelCount) {
    out.state = proto::CalState::none;
  } else if (unset != 0 || ids_differ) {
    out.state = proto::CalState::mixed;
  } else {
    out.state = proto::CalState::active;
    out.cal_id = first_id;
  }
  return out;
}

}  // namespace fw
}  // namespace driftlab
