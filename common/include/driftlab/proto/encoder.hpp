// Encoder: writes one protocol v2 frame into a caller's buffer (no state, no heap). Spec: docs/protocol.md §1-§2.
//
// Every function returns the frame size written [bytes], or 0 when the frame does not fit in `out_size` (nothing
// useful is written then). `seq` is the sender's frame counter; the caller increments it per frame sent.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "driftlab/proto/command_auth.hpp"
#include "driftlab/proto/messages.hpp"
#include "driftlab/proto/msg_table.hpp"
#include "driftlab/proto/nodiscard.hpp"

namespace driftlab {
namespace proto {

/// Frames an already serialized payload. Also returns 0 when `type` is unknown, authenticated (below), or
/// `payload_len` is not the type's fixed length, so a malformed frame can never be produced.
DRIFTLAB_NODISCARD size_t encode_frame(uint8_t type, uint16_t seq, const uint8_t* payload, size_t payload_len,
                                       uint8_t* out, size_t out_size);

/// Frames the serialized fields of an authenticated type (command_auth.hpp) with their trailer under `auth`; returns 0
/// when `type` is not authenticated or `fields_len` is not its fields' length.
DRIFTLAB_NODISCARD size_t encode_authenticated(uint8_t type, uint16_t seq, const uint8_t* fields, size_t fields_len,
                                               const CommandAuth& auth, uint8_t* out, size_t out_size);

DRIFTLAB_NODISCARD size_t encode_hello(uint16_t seq, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t encode_version(const VersionPayload& p, uint16_t seq, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t encode_config_get(uint16_t seq, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t encode_config_set(const ConfigPayload& p, const CommandAuth& auth, uint16_t seq, uint8_t* out,
                                            size_t out_size);
DRIFTLAB_NODISCARD size_t encode_config(const ConfigPayload& p, uint16_t seq, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t encode_poll(uint16_t seq, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t encode_sample(const SamplePayload& p, uint16_t seq, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t encode_raw(const RawPayload& p, uint16_t seq, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t encode_ack(const AckPayload& p, uint16_t seq, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t encode_nak(const NakPayload& p, uint16_t seq, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t encode_status_get(uint16_t seq, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t encode_status(const StatusPayload& p, uint16_t seq, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t encode_cal_set(const CalPayload& p, const CommandAuth& auth, uint16_t seq, uint8_t* out,
                                         size_t out_size);
/// KEY_SET of `new_key`, sealed under auth.key (which must be set: an open board takes no KEY_SET; else 0).
DRIFTLAB_NODISCARD size_t encode_key_set(const Key& new_key, const CommandAuth& auth, uint16_t seq, uint8_t* out,
                                         size_t out_size);
DRIFTLAB_NODISCARD size_t encode_cal_get(const CalGetPayload& p, uint16_t seq, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t encode_cal(const CalPayload& p, uint16_t seq, uint8_t* out, size_t out_size);

/// Version-1 peers (docs/protocol.md §1.1): a v1 HELLO, which a host sends when a board does not answer v2's (a v1
/// board answers it with its own VERSION, naming its version); and the v1 VERSION a v2 board answers a v1 HELLO with,
/// whose proto_version 2 a v1 host refuses by number. `out_size` must hold a v2 VERSION frame (the payload is
/// serialized whole, then cut to v1's 20 bytes).
DRIFTLAB_NODISCARD size_t encode_legacy_hello(uint16_t seq, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t encode_legacy_version(const VersionPayload& p, uint16_t seq, uint8_t* out, size_t out_size);

}  // namespace proto
}  // namespace driftlab
