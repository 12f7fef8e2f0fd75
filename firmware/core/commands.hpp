// Commands: one decoded host frame -> the reply it deserves, and for CONFIG_SET the validated new Config.
// Pure decision, no side effects: the Firmware applies a change only on Reply::ack, so a NAK changes nothing.
// Spec: docs/protocol.md §3 (types, directions) and §4 (Status); docs/firmware.md §1 "Architecture" (check order).
#pragma once

#include <stdint.h>

#include "driftlab/proto/command_auth.hpp"
#include "driftlab/proto/messages.hpp"
#include "driftlab/proto/nodiscard.hpp"
#include "driftlab/proto/status.hpp"
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
  key_ack,  ///< KEY_SET accepted: unseal the new key with the old one, store it, then ACK
};

/// What the board knows to check a command's trailer (command_auth.hpp): its key and the last counter it admitted.
struct AuthView {
  proto::AuthState state;
  const proto::Key* key;  ///< meaningful when state is keyed
  uint32_t counter;       ///< last counter admitted
};

struct CommandOutcome {
  Reply reply;
  Config config;          ///< the validated new configuration, meaningful for Reply::ack
  proto::AckPayload ack;  ///< meaningful for Reply::ack and Reply::cal_ack
  proto::NakPayload nak;  ///< meaningful for Reply::nak
  proto::CalPayload cal;  ///< the validated entry for Reply::cal_ack; the channel asked for Reply::cal
};

/// The authentication verdict on a decoded `frame` (docs/security.md): ok for a type without a trailer, for a length
/// decide() refuses anyway, and for any command to an open board but KEY_SET (not_allowed: an open board has no key
/// to seal a new one under). On a keyed board: unauthenticated unless the tag verifies, then replayed unless the
/// counter is above the last admitted. A damaged key refuses every command that changes the board (unauthenticated).
DRIFTLAB_NODISCARD proto::Status check_auth(const uint8_t* frame, const AuthView& auth);

/// Decides the answer to a frame of type `type_id` and sequence `seq` carrying `payload_len` bytes while the
/// firmware runs in `mode`, with `auth` check_auth()'s verdict. Checks, in order: the type is known (else NAK
/// unknown_type), host-to-firmware (else not_allowed), the length is the type's fixed length (else bad_length), the
/// authentication (NAK with its verdict), then CONFIG_SET's and CAL_SET's fields (out_of_range with the field index),
/// and a POLL's mode: in stream mode it is NAKed not_allowed, so no SAMPLE lands off the output grid. An
/// unauthenticated sender so learns nothing of which fields a board would take.
DRIFTLAB_NODISCARD CommandOutcome decide(uint8_t type_id, uint16_t seq, const uint8_t* payload, uint8_t payload_len,
                                         proto::OutputMode mode, proto::Status auth);

}  // namespace fw
}  // namespace driftlab
