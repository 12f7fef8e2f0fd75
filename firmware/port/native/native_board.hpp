// NativeBoard: the HAL of the native port, a virtual ATmega328P board that tests and the simulator drive in
// virtual time, deterministically. Contract: firmware/core/hal.hpp, docs/hal.md "Native port".
//
// How to drive it (one board per thread; the board constructed last on a thread is that thread's HAL):
//
//   fw::NativeBoard board;          // installs itself as this thread's HAL
//   fw::Firmware firmware;
//   firmware.start();               // calls hal_init(): board.armed() is now true
//   while (running) {
//     // 1. conversions due by the virtual time t [ticks], exactly as the AVR's Timer1 would trigger them
//     while (board.next_conversion_time_ticks() <= t) {
//       board.set_time_ticks(board.next_conversion_time_ticks());
//       board.convert(code_for(board.next_channel(), board.time_ticks()));   // the ADC interrupt
//       board.service(firmware);                                            // the main loop
//     }
//     board.set_time_ticks(t);
//     board.receive(bytes_from_host, n);  board.service(firmware);           // the UART RX interrupt
//     n_out = board.transmit(out, sizeof out);                               // the UART TX interrupt
//   }
//
// advance_to() is that loop for a code source that is a function of (channel, time). Conversions carry the
// trigger tick of the schedule (as the AVR port stamps them), not whatever time the caller set, so native and
// AVR frames are byte-identical for the same codes. Time is kept in 64 bits; hal_ticks() is its low 32 bits.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "driftlab/channels.hpp"
#include "firmware/core/firmware.hpp"
#include "firmware/core/hal.hpp"
#include "firmware/core/spsc_ring.hpp"

namespace driftlab {
namespace fw {

class NativeBoard {
 public:
  NativeBoard();
  ~NativeBoard();
  NativeBoard(const NativeBoard&) = delete;
  NativeBoard& operator=(const NativeBoard&) = delete;

  // ---- What the firmware armed through hal_init() ----
  /// True once hal_init() ran.
  bool armed() const { return armed_; }
  /// The schedule of the last hal_init() (zeroed before).
  const AdcSchedule& schedule() const { return schedule_; }
  /// Period between conversion triggers [ticks]; 0 before hal_init().
  uint16_t conversion_period_ticks() const { return schedule_.conversion_period_ticks; }
  /// Channel the next convert() samples (the round-robin of the AVR's ADC interrupt).
  Channel next_channel() const { return schedule_.order[next_index_]; }
  /// Trigger time of the next conversion [ticks, 64-bit]; UINT64_MAX before hal_init().
  uint64_t next_conversion_time_ticks() const { return armed_ ? next_trigger_ticks_ : UINT64_MAX; }
  /// Number of hal_init() calls so far (a CONFIG_SET that changed the timing re-arms).
  uint32_t arm_count() const { return arm_count_; }

  // ---- Virtual time ----
  /// Sets the current time [ticks]; hal_ticks() returns its low 32 bits. Time may only move forward.
  void set_time_ticks(uint64_t time_ticks);
  uint64_t time_ticks() const { return time_ticks_; }

  // ---- Interrupt side ----
  /// As the ADC interrupt: records `code_counts` (0..1023) for next_channel(), stamped with the trigger time
  /// next_conversion_time_ticks() (low 32 bits), then advances the round-robin and the schedule. Returns false
  /// when the conversion ring is full: the conversion is lost, as on the chip, and the firmware counts it.
  bool convert(uint16_t code_counts);
  /// True when the next convert() is the round's last and a temperature was requested: that convert() also queues
  /// the die temperature conversion (hal.hpp hal_request_temperature()), of die_temperature_code() then.
  bool temperature_due() const { return temperature_requested_ && next_index_ == kChannelCount - 1U; }
  /// What the die temperature sensor reads now, 0..1023 (the chip's ADC8 input): hal_read_temperature() at start and
  /// each requested conversion take it. Default: the datasheet's typical code at 25 °C.
  void set_die_temperature_code(uint16_t code) { die_temperature_code_ = code; }
  uint16_t die_temperature_code() const { return die_temperature_code_; }
  /// As the UART RX interrupt: queues bytes; returns how many fit, the rest count as rx overflow.
  size_t receive(const uint8_t* bytes, size_t count);
  /// As the UART TX interrupt: moves up to `capacity` queued bytes into `out`; returns how many.
  size_t transmit(uint8_t* out, size_t capacity);
  /// Bytes queued for transmission.
  size_t tx_pending() const { return tx_ring_.size(); }

  // ---- Main loop ----
  /// One pass of the AVR main loop: drains the conversion ring into firmware.on_conversion(), then the receive
  /// ring into firmware.on_rx_byte().
  void service(Firmware& firmware);

  /// Runs every conversion due by `time_ticks`, each followed by service(), with codes from
  /// `code_for(Channel, uint64_t trigger_time_ticks) -> uint16_t`; leaves the time at `time_ticks`.
  template <typename CodeSource>
  void advance_to(uint64_t time_ticks, Firmware& firmware, CodeSource&& code_for) {
    while (next_conversion_time_ticks() <= time_ticks) {
      set_time_ticks(next_conversion_time_ticks());
      static_cast<void>(convert(code_for(next_channel(), time_ticks_)));
      service(firmware);
    }
    set_time_ticks(time_ticks);
    service(firmware);
  }

  // ---- What outlives a reset ----
  /// The EEPROM, erased (0xFF) at construction. A test moves it into the next board to model a reset or a power
  /// cycle (a Firmware constructed afresh on a board holding the old contents).
  uint8_t* eeprom() { return eeprom_; }
  const uint8_t* eeprom() const { return eeprom_; }
  /// Copies `image` (its first kEepromBytes at most) into the EEPROM from address 0: a board powered on with what an
  /// upload, a programmer or an earlier board left there.
  void load_eeprom(const uint8_t* image, size_t size);
  /// What hal_reset_info() reports: power-on unless a test models another reset.
  void set_reset_info(const ResetInfo& info) { reset_info_ = info; }
  const ResetInfo& reset_info() const { return reset_info_; }

  // ---- Used by the HAL functions of this port (hal_native.cpp) ----
  void on_hal_init(const AdcSchedule& schedule);
  uint8_t on_hal_uart_write(const uint8_t* bytes, uint8_t count);
  void on_hal_request_temperature() { temperature_requested_ = true; }
  uint16_t rx_overflow_count() const { return rx_overflow_bytes_; }
  /// The board of the calling thread, or nullptr.
  static NativeBoard* current();

 private:
  AdcSchedule schedule_;
  bool armed_;
  uint8_t next_index_;
  uint32_t arm_count_;
  uint64_t next_trigger_ticks_;
  uint64_t time_ticks_;
  uint16_t rx_overflow_bytes_;
  bool temperature_requested_;
  uint16_t die_temperature_code_;
  ResetInfo reset_info_;
  uint8_t eeprom_[kEepromBytes];
  SpscRing<Conversion, kAdcRingCapacity> adc_ring_;
  SpscRing<uint8_t, kRxRingCapacity> rx_ring_;
  SpscRing<uint8_t, kTxRingCapacity> tx_ring_;
  NativeBoard* previous_;  // the thread's board before this one, restored on destruction
};

}  // namespace fw
}  // namespace driftlab
