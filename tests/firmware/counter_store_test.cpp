// CounterStore on the native board's EEPROM: it only grows, survives a reset (a new store reading the same EEPROM),
// spreads its writes over every slot in turn, and a write cut short leaves the value before it.
#include "firmware/core/counter_store.hpp"

#include <gtest/gtest.h>

#include <cstdint>

#include "driftlab/proto/byte_order.hpp"
#include "firmware/port/native/native_board.hpp"

namespace driftlab {
namespace fw {
namespace {

uint32_t slot_value(const NativeBoard& board, uint8_t slot) {
  return proto::get_u32_le(board.eeprom() + kCounterEepromAddress + slot * kCounterSlotBytes);
}

TEST(CounterStore, AnErasedEepromCountsFromZero) {
  NativeBoard board;
  CounterStore counter;
  counter.load();
  EXPECT_EQ(counter.value(), 0u);
}

TEST(CounterStore, EveryValueSurvivesAResetAndTheSlotsAreWrittenInTurn) {
  NativeBoard board;
  for (uint32_t k = 1; k <= 3 * kCounterSlots + 5; ++k) {
    CounterStore after_reset;  // each value written by a store that booted afresh
    after_reset.load();
    ASSERT_EQ(after_reset.value(), k - 1);
    after_reset.advance_to(k);
    // Value k lies in slot (k - 1) mod 8: each slot takes one write in eight.
    EXPECT_EQ(slot_value(board, static_cast<uint8_t>((k - 1) % kCounterSlots)), k);
  }
  CounterStore last;
  last.load();
  EXPECT_EQ(last.value(), 3u * kCounterSlots + 5);
}

TEST(CounterStore, AWriteCutShortLeavesTheValueBeforeIt) {
  NativeBoard board;
  CounterStore counter;
  counter.load();
  counter.advance_to(41);
  counter.advance_to(42);
  // The reset struck after the value's bytes and before its complement's: slot 2 holds 43 and an erased complement.
  uint8_t* slot2 = board.eeprom() + kCounterEepromAddress + 2 * kCounterSlotBytes;
  proto::put_u32_le(slot2, 43);
  proto::put_u32_le(slot2 + 4, 0xFFFFFFFFUL);
  CounterStore after_reset;
  after_reset.load();
  EXPECT_EQ(after_reset.value(), 42u);
  // The next write goes to that slot again, and holds.
  after_reset.advance_to(43);
  CounterStore again;
  again.load();
  EXPECT_EQ(again.value(), 43u);
}

TEST(CounterStore, ALargeJumpIsKeptAsTheLargest) {
  NativeBoard board;
  CounterStore counter;
  counter.load();
  counter.advance_to(7);
  counter.advance_to(0xFFFFFF00UL);
  CounterStore after_reset;
  after_reset.load();
  EXPECT_EQ(after_reset.value(), 0xFFFFFF00UL);
}

}  // namespace
}  // namespace fw
}  // namespace driftlab
