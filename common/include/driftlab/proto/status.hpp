// Status: the NAK reasons of protocol v2 (v1's, and three appended), one enum with stable numbers (docs/protocol.md
// §4). Firmware functions that can fail return it; the numbers travel in NAK frames, so never renumber, only append.
#pragma once

#include <stdint.h>

namespace driftlab {
namespace proto {

enum class Status : uint8_t {
  ok = 0,               ///< accepted
  bad_length = 1,       ///< payload length differs from the type's fixed length
  unknown_type = 2,     ///< type not in the message table
  out_of_range = 3,     ///< a field outside its documented range (NAK.field names it)
  bad_version = 4,      ///< frame version byte is not kProtocolVersion
  not_allowed = 5,      ///< not in this state: a firmware-to-host type sent to the firmware, or POLL in stream mode
  busy = 6,             ///< reserved: valid request the firmware cannot serve now; the firmware never sends it
  not_stored = 7,       ///< CAL_GET of an entry that is erased or fails its CRC
  unauthenticated = 8,  ///< a command that changes the board whose tag does not verify under the board's key
  replayed = 9,         ///< a command with a valid tag whose counter is not above the last one admitted
};

constexpr uint8_t kStatusCount = 10;

/// Lower-case name of a status ("out_of_range"), or nullptr for a number this version does not know. For host
/// text; the firmware never needs it, so the strings stay out of its image.
const char* status_name(Status status);

}  // namespace proto
}  // namespace driftlab
