// The firmware HAL: what the pure-logic core asks of a board, and the two events a board feeds into the core.
// Ports: firmware/port/avr (ATmega328P registers) and firmware/port/native (NativeBoard, virtual time).
// Contract and port notes: docs/hal.md.
//
// How it fits together (who calls what, in which context and unit):
//  - At start, and after an accepted CONFIG_SET changed the timing, the core calls hal_init() from the main loop
//    with an AdcSchedule: the tick of the first trigger, a conversion period [ticks] and the round-robin order.
//    The port arms a timer that triggers one ADC conversion per period; its ADC interrupt reads the 10-bit code
//    [counts], selects the next channel of the order for the following conversion, and pushes a Conversion
//    {channel, code, tick of the trigger} into a ring of kAdcRingCapacity. A full ring loses the conversion; the
//    core sees the gap in the ticks and counts it.
//  - The UART receive interrupt pushes bytes into a ring of kRxRingCapacity (counting bytes lost to a full ring,
//    see hal_rx_overflow_count()); the transmit interrupt drains the ring filled by hal_uart_write().
//  - The port's main loop drains the conversion ring into Firmware::on_conversion() and the receive ring into
//    Firmware::on_rx_byte(), then calls hal_idle(). Events never enter the core from an interrupt.
//  - Time is ticks of kTickHz on both ports, so native and AVR frames are byte-identical.
#pragma once

#include <stdint.h>

#include "driftlab/channels.hpp"
#include "driftlab/proto/nodiscard.hpp"

namespace driftlab {
namespace fw {

/// Rate of hal_ticks() and of every tick in frames [Hz]: Timer1 at 16 MHz / 64 on the ATmega328P.
constexpr uint32_t kTickHz = 250000;
constexpr uint32_t kTicksPerMs = kTickHz / 1000;
static_assert(kTickHz % 1000 == 0, "ms to ticks conversions assume a whole number of ticks per ms");

/// Ring sizes shared by both ports so that overflow behaviour is the same natively and on the chip.
/// Conversions: 16 x 7 bytes absorb one output's burst of work (divisions, framing) at the fastest schedule.
constexpr uint8_t kAdcRingCapacity = 16;
/// Received bytes: one of the longest host frames (CAL_SET, KEY_SET: 37 bytes) and most of another; a host sends one
/// command and waits for its answer.
constexpr uint8_t kRxRingCapacity = 64;
/// Bytes to send: SAMPLE + RAW (59 bytes) plus two replies, with room to spare.
constexpr uint8_t kTxRingCapacity = 128;

/// What hal_init() arms: a first conversion at `first_trigger_tick`, then one every `conversion_period_ticks`,
/// channels in `order`, repeating.
struct AdcSchedule {
  /// Trigger time of conversion 0 [ticks]. The core puts it on its own tick grid (one old period after the
  /// conversion that ended the old schedule, or one period after start), so that the new grid does not depend on
  /// how long the main loop took to get there and every port arms the same grid.
  uint32_t first_trigger_tick;
  uint16_t conversion_period_ticks;  ///< time between two conversion triggers [ticks], >= 1
  Channel order[kChannelCount];      ///< channel of conversion 0, 1, 2, 3 after arming, then again from 0
};

/// A first trigger closer than this to the arming instant, already past, or further than 65536 ticks (one Timer1
/// cycle) cannot be armed as asked: ports then trigger first one period after the call instead.
constexpr uint32_t kMinArmWaitTicks = 2;
constexpr uint32_t kMaxArmWaitTicks = 65536;

/// Ticks from hal_init() at `now_tick` to the first trigger: as asked when armable, else one period (above).
/// Shared by both ports so they choose alike.
inline uint32_t arm_wait_ticks(const AdcSchedule& schedule, uint32_t now_tick) {
  const uint32_t wait = schedule.first_trigger_tick - now_tick;  // wraps to a huge value when already past
  return wait >= kMinArmWaitTicks && wait <= kMaxArmWaitTicks ? wait : schedule.conversion_period_ticks;
}

/// One finished conversion as the ADC interrupt records it.
struct Conversion {
  Channel channel;       ///< channel the multiplexer selected for this conversion
  uint16_t code_counts;  ///< 10-bit result [counts], 0..1023
  uint32_t tick;         ///< time of the trigger that started it [ticks]; consecutive conversions differ by
                         ///< exactly conversion_period_ticks unless some were lost
};

/// Conversion.channel of a die temperature conversion (ADC8, against the internal 1.1 V reference): no sensor
/// channel, never in a round (hal_request_temperature()).
constexpr Channel kTemperatureInput = static_cast<Channel>(8);

/// The shortest conversion period that leaves the port room for a temperature conversion between the round's last
/// conversion and the next trigger [ticks]: two conversions of 13 ADC clocks (the first after switching the
/// reference is discarded), 208 us, after the 108 us of the round's last, with the vectors' latency and a margin.
constexpr uint16_t kMinTemperaturePeriodTicks = 125;

/// Why the chip last reset, as VERSION reports it: the ATmega328P MCUSR bits.
constexpr uint8_t kResetPowerOn = 0x01;
constexpr uint8_t kResetExternal = 0x02;
constexpr uint8_t kResetBrownOut = 0x04;
constexpr uint8_t kResetWatchdog = 0x08;

struct ResetInfo {
  uint8_t cause;         ///< kReset* bits
  uint16_t assert_line;  ///< line of the DRIFTLAB_ASSERT that forced the reset, 0 = none
};

/// Main loop, at start and on schedule changes. Stops any running schedule, waits for a conversion in progress,
/// drops conversions still queued from it, and arms `schedule`: conversion 0 samples order[0] at
/// schedule.first_trigger_tick (see arm_wait_ticks()). hal_ticks() keeps counting across calls.
void hal_init(const AdcSchedule& schedule);

/// Main loop, before the first hal_init() (the ADC idle): converts the die temperature twice against the internal
/// 1.1 V reference, the first after switching discarded, and returns the second code, 0..1023 (docs/hal.md §1.4).
uint16_t hal_read_temperature();

/// Main loop, while a schedule of conversion_period_ticks >= kMinTemperaturePeriodTicks runs: right after the next
/// conversion of the round's last slot (order[3]) the port converts the die temperature once and queues it as a
/// Conversion {kTemperatureInput, code, that conversion's trigger tick}, between that conversion and the next, so the
/// core sees it at the same place in the stream on every port. hal_init() drops a request not yet served.
void hal_request_temperature();

/// Main loop. Queues `count` bytes for transmission if all of them fit, else none: the core never sends half a
/// frame. Never blocks. Returns the bytes accepted, `count` or 0.
DRIFTLAB_NODISCARD uint8_t hal_uart_write(const uint8_t* bytes, uint8_t count);

/// Any context. Free-running time [ticks of kTickHz], wraps every 2^32 ticks (4.77 h).
uint32_t hal_ticks();

/// Main loop, when both rings are empty: sleeps until the next interrupt on the chip, returns at once natively.
void hal_idle();

/// Main loop. Bytes lost because the receive ring was full, since reset, saturating at 0xFFFF [bytes].
uint16_t hal_rx_overflow_count();

/// Main loop. Cause of the last reset and the assertion line behind it.
ResetInfo hal_reset_info();

/// Bytes of EEPROM the core may use (the ATmega328P's 1 KiB); it keeps there what must outlive a reset: the
/// calibration (cal_store.hpp). An erased byte reads 0xFF.
constexpr uint16_t kEepromBytes = 1024;

/// Main loop. Copies `count` bytes of EEPROM from `address` into `out` (address + count <= kEepromBytes).
void hal_eeprom_read(uint16_t address, uint8_t* out, uint8_t count);

/// Main loop. Writes `count` bytes to EEPROM at `address`, skipping bytes that already hold their value (each
/// write wears a cell, ~100 000 writes). Blocks until written: ~3.4 ms a changed byte on the chip, during which
/// conversions queue in their ring and may be lost (and counted).
void hal_eeprom_write(uint16_t address, const uint8_t* bytes, uint8_t count);

/// Any context, never returns. Called by DRIFTLAB_ASSERT with the failing line: natively prints and aborts; on
/// the chip stores the line for the next VERSION and resets through the watchdog.
[[noreturn]] void hal_assert_failed(uint16_t line);

}  // namespace fw
}  // namespace driftlab

/// Programmer errors only (a port breaking the contract); bad input is a Status or a counter, never an assert.
/// Only the line travels: the chip has no room for file names (docs/hal.md §1.3 "Assertions").
#define DRIFTLAB_ASSERT(cond) \
  ((cond) ? static_cast<void>(0) : ::driftlab::fw::hal_assert_failed(static_cast<uint16_t>(__LINE__)))
