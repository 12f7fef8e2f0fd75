// Commands: one decoded host frame -> the reply it deserves, and for CONFIG_SET the validated new Config.
// Pure decision, no side effects: the Firmware applies a change only on Reply::ack, so a NAK changes nothing.
// Spec: docs/protocol.md §3 (types, directions) and §4 (Status); docs/firmware.md §1 "Architecture" (check order).
#pragma once

#include <stdint.h>

#include "driftlab/proto/messages.hpp"
#include "driftlab/proto/nodiscard.hpp"
#include "firmware/core/config.hpp"

namespace driftlab {
namespace fw {

/// What the firmware sends back.
enum class Reply : uint8_t {
  version,  ///< HELLO -> VERSION
  config,   ///< CONFIG_GET -> CONFIG
  sample,   ///< POLL in poll mode -> SAMPLE (+ RAW in raw mode)
  status,   ///< STATUS_GET -> STATUS
  ack,      ///< CONFIG_SET accepted: apply `config`, then ACK
  nak,      ///< refused: send `nak`, change nothing
  cal_ack,  ///< CAL_SET accepted: store `cal` as its channel's entry, reload the calibration, then ACK
  cal,      ///< CAL_GET -> CAL of channel `cal.channel` (or NAK not_stored when that entry is unset or damaged)
};

struct CommandOutcome {
  Reply reply;
  Config config;          ///< the validated new configuration, meaningful for Reply::ack
  proto::AckPayload ack;  ///< meaningful for Reply::ack and Reply::cal_ack
  proto::NakPayload nak;  ///< meaningful for Reply::nak
  proto::CalPayload cal;  ///< the validated entry for Reply::cal_ack; the channel asked for Reply::cal
};

/// Decides the answer to a frame of type `type_id` and sequence `seq` carrying `payload_len` bytes while the
/// firmware runs in `mode`. Checks, in order: the type is known (else NAK unknown_type), host-to-firmware (else
/// not_allowed), the length is the type's fixed length (else bad_length), then CONFIG_SET's and CAL_SET's fields
/// (out_of_range with the field index), and a POLL's mode: in stream mode it is NAKed not_allowed, so no SAMPLE lands
/// off the output grid.
DRIFTLAB_NODISCARD CommandOutcome decide(uint8_t type_id, uint16_t seq, const uint8_t* payload, uint8_t payload_len,
                                         proto::OutputMode mode);

}  // namespace fw
}  // namespace driftlab
