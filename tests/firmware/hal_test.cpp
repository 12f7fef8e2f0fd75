// arm_wait_ticks(): the one rule both ports use to place the first trigger of a schedule (hal.hpp, docs/hal.md
// §1.1): as asked when 2..65536 ticks ahead, else one period after the call; correct across the tick wrap.
#include "firmware/core/hal.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace driftlab {
namespace fw {
namespace {

AdcSchedule schedule_at(uint32_t first_trigger_tick, uint16_t period_ticks) {
  AdcSchedule s = {};
  s.first_trigger_tick = first_trigger_tick;
  s.conversion_period_ticks = period_ticks;
  return s;
}

TEST(ArmWait, FirstTriggerWithinOneTimerCycleIsKeptExactly) {
  EXPECT_EQ(arm_wait_ticks(schedule_at(1002, 250), 1000), 2U);
  EXPECT_EQ(arm_wait_ticks(schedule_at(1250, 250), 1000), 250U);
  EXPECT_EQ(arm_wait_ticks(schedule_at(1000 + 65536, 250), 1000), 65536U);
}

TEST(ArmWait, UnarmableFirstTriggerFallsBackToOnePeriod) {
  EXPECT_EQ(arm_wait_ticks(schedule_at(1000, 250), 1000), 250U);          // now
  EXPECT_EQ(arm_wait_ticks(schedule_at(1001, 250), 1000), 250U);          // too close for the timer
  EXPECT_EQ(arm_wait_ticks(schedule_at(990, 250), 1000), 250U);           // already past
  EXPECT_EQ(arm_wait_ticks(schedule_at(1000 + 65537, 250), 1000), 250U);  // beyond one Timer1 cycle
}

TEST(ArmWait, WorksAcrossTheTickWrap) {
  EXPECT_EQ(arm_wait_ticks(schedule_at(100, 625), 0xFFFFFF00U), 356U);
  EXPECT_EQ(arm_wait_ticks(schedule_at(0xFFFFFF00U, 625), 100), 625U);  // far in the past across the wrap
}

}  // namespace
}  // namespace fw
}  // namespace driftlab
