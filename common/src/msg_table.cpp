// Lookups into the message table (msg_table.hpp). Ids are dense from 1 (checked there), so a lookup is an index.
#include "driftlab/proto/msg_table.hpp"

namespace driftlab {
namespace proto {
namespace {

constexpr MsgSpec spec_at(size_t i) {
  return MsgSpec{kMsgTable[i].payload_len, kMsgTable[i].crc_seed, kMsgTable[i].direction};
}

// Name-free copy evaluated at compile time: only these 3 bytes per type reach the firmware image.
constexpr MsgSpec kSpecs[] = {spec_at(0),  spec_at(1),  spec_at(2),  spec_at(3), spec_at(4),  spec_at(5),
                              spec_at(6),  spec_at(7),  spec_at(8),  spec_at(9), spec_at(10), spec_at(11),
                              spec_at(12), spec_at(13), spec_at(14), spec_at(15)};
static_assert(sizeof(kSpecs) / sizeof(kSpecs[0]) == kMsgTypeCount, "kSpecs must list every row of kMsgTable");

bool is_known(uint8_t id) { return id >= 1 && id <= kMsgTypeCount; }

}  // namespace

const MsgInfo* find_msg(uint8_t id) { return is_known(id) ? &kMsgTable[id - 1] : nullptr; }

bool find_spec(uint8_t id, MsgSpec* spec) {
  if (!is_known(id)) {
    return false;
  }
  *spec = kSpecs[id - 1];
  return true;
}

}  // namespace proto
}  // namespace driftlab
