// CounterStore: slots, validity and rotation (counter_store.hpp).
#include "firmware/core/counter_store.hpp"

#include "driftlab/proto/byte_order.hpp"
#include "firmware/core/hal.hpp"

namespace driftlab {
namespace fw {
namespace {

uint16_t slot_address(uint8_t slot) {
  return static_cast<uint16_t>(kCounterEepromAddress + static_cast<uint16_t>(slot) * kCounterSlotBytes);
}

}  // namespace

void CounterStore::load() {
  value_ = 0;
  slot_ = kCounterSlots - 1;  // with no valid slot, the first write goes to slot 0
  for (uint8_t s = 0; s < kCounterSlots; ++s) {
    uint8_t bytes[kCounterSlotBytes];
    hal_eeprom_read(slot_address(s), bytes, kCounterSlotBytes);
    const uint32_t v = proto::get_u32_le(bytes);
    if (proto::get_u32_le(bytes + 4) == static_cast<uint32_t>(~v) && v >= value_) {
      value_ = v;
      slot_ = s;
    }
  }
}

void CounterStore::advance_to(uint32_t next) {
  DRIFTLAB_ASSERT(next > value_);
  slot_ = static_cast<uint8_t>((slot_ + 1U) % kCounterSlots);
  uint8_t bytes[kCounterSlotBytes];
  proto::put_u32_le(bytes, next);
  proto::put_u32_le(bytes + 4, ~next);
  hal_eeprom_write(slot_address(slot_), bytes, kCounterSlotBytes);
  value_ = next;
}

}  // namespace fw
}  // namespace driftlab
