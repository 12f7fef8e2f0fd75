// Message table of protocol v2: per type its id, name, fixed payload length, CRC seed byte and direction, in one
// table sorted by id. Spec and the seed derivation: docs/protocol.md §2-§3.
//
// The decoder and the firmware use find_spec(), which reads a name-free copy of the table built at compile time,
// so the names never occupy the ATmega328P's RAM (avr-gcc keeps const data in RAM).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "driftlab/proto/nodiscard.hpp"

namespace driftlab {
namespace proto {

enum class MsgType : uint8_t {
  hello = 0x01,
  version = 0x02,
  config_get = 0x03,
  config_set = 0x04,
  config = 0x05,
  poll = 0x06,
  sample = 0x07,
  raw = 0x08,
  ack = 0x09,
  nak = 0x0A,
  status_get = 0x0B,
  status = 0x0C,
  cal_set = 0x0D,
  cal_get = 0x0E,
  cal = 0x0F,
  key_set = 0x10,
};

constexpr uint8_t type_id(MsgType type) { return static_cast<uint8_t>(type); }

/// Who sends a type. The firmware NAKs a fw_to_host type with Status::not_allowed.
enum class Direction : uint8_t { host_to_fw = 0, fw_to_host = 1 };

struct MsgInfo {
  MsgType type;
  const char* name;     ///< upper-case protocol name ("CONFIG_SET")
  uint8_t payload_len;  ///< fixed payload length [bytes]; any other length is rejected
  uint8_t crc_seed;     ///< folded into the CRC after the payload (CRC_EXTRA idea, docs/protocol.md §2)
  Direction direction;
};

/// Seeds: low byte XOR high byte of CRC-16/IBM-3740 over the type's definition string (docs/protocol.md §2;
/// tests/common/msg_table_test.cpp recomputes every one).
constexpr MsgInfo kMsgTable[] = {
    {MsgType::hello, "HELLO", 0, 0x9F, Direction::host_to_fw},
    {MsgType::version, "VERSION", 28, 0xA2, Direction::fw_to_host},
    {MsgType::config_get, "CONFIG_GET", 0, 0xF3, Direction::host_to_fw},
    {MsgType::config_set, "CONFIG_SET", 19, 0x25, Direction::host_to_fw},
    {MsgType::config, "CONFIG", 7, 0x6A, Direction::fw_to_host},
    {MsgType::poll, "POLL", 0, 0x8F, Direction::host_to_fw},
    {MsgType::sample, "SAMPLE", 29, 0x0E, Direction::fw_to_host},
    {MsgType::raw, "RAW", 12, 0xB0, Direction::fw_to_host},
    {MsgType::ack, "ACK", 3, 0xB4, Direction::fw_to_host},
    {MsgType::nak, "NAK", 5, 0x11, Direction::fw_to_host},
    {MsgType::status_get, "STATUS_GET", 0, 0x90, Direction::host_to_fw},
    {MsgType::status, "STATUS", 27, 0xDB, Direction::fw_to_host},
    {MsgType::cal_set, "CAL_SET", 28, 0xC9, Direction::host_to_fw},
    {MsgType::cal_get, "CAL_GET", 1, 0x44, Direction::host_to_fw},
    {MsgType::cal, "CAL", 16, 0x9E, Direction::fw_to_host},
    {MsgType::key_set, "KEY_SET", 28, 0x1E, Direction::host_to_fw},
};

constexpr size_t kMsgTypeCount = sizeof(kMsgTable) / sizeof(kMsgTable[0]);

namespace detail {
// Ids are dense from 1, so lookup is an index, and the sort order is checked here rather than trusted.
constexpr bool table_is_dense_from_one(size_t i) {
  return i == kMsgTypeCount || (type_id(kMsgTable[i].type) == i + 1 && table_is_dense_from_one(i + 1));
}
}  // namespace detail
static_assert(detail::table_is_dense_from_one(0), "kMsgTable must be sorted by id, ids 1..N without gaps");

/// The table row of type id `id`, or nullptr when the id is unknown.
DRIFTLAB_NODISCARD const MsgInfo* find_msg(uint8_t id);

/// What the wire needs to know about a type, without its name.
struct MsgSpec {
  uint8_t payload_len;  ///< [bytes]
  uint8_t crc_seed;
  Direction direction;
};

/// Fills `*spec` for type id `id` and returns true, or returns false (leaving `*spec` alone) when unknown.
DRIFTLAB_NODISCARD bool find_spec(uint8_t id, MsgSpec* spec);

/// Fixed payload length of a known type [bytes].
constexpr uint8_t payload_len_of(MsgType type) { return kMsgTable[type_id(type) - 1].payload_len; }

}  // namespace proto
}  // namespace driftlab
