// The HAL of the native port: every call goes to the calling thread's NativeBoard (native_board.hpp).
#include <stdio.h>
#include <stdlib.h>

#include "firmware/core/critical.hpp"
#include "firmware/core/hal.hpp"
#include "firmware/port/native/native_board.hpp"

namespace driftlab {
namespace fw {
namespace {

NativeBoard& board() {
  NativeBoard* b = NativeBoard::current();
  DRIFTLAB_ASSERT(b != nullptr);
  return *b;
}

}  // namespace

void hal_init(const AdcSchedule& schedule) { board().on_hal_init(schedule); }

uint16_t hal_read_temperature() { return board().die_temperature_code(); }

void hal_request_temperature() { board().on_hal_request_temperature(); }

uint8_t hal_uart_write(const uint8_t* bytes, uint8_t count) { return board().on_hal_uart_write(bytes, count); }

uint32_t hal_ticks() { return static_cast<uint32_t>(board().time_ticks()); }

void hal_idle() {}

uint16_t hal_rx_overflow_count() { return board().rx_overflow_count(); }

ResetInfo hal_reset_info() { return board().reset_info(); }

void hal_eeprom_read(uint16_t address, uint8_t* out, uint8_t count) {
  DRIFTLAB_ASSERT(address + count <= kEepromBytes);
  for (uint8_t i = 0; i < count; ++i) {
    out[i] = board().eeprom()[address + i];
  }
}

void hal_eeprom_write(uint16_t address, const uint8_t* bytes, uint8_t count) {
  DRIFTLAB_ASSERT(address + count <= kEepromBytes);
  for (uint8_t i = 0; i < count; ++i) {
    board().eeprom()[address + i] = bytes[i];
  }
}

void hal_assert_failed(uint16_t line) {
  fprintf(stderr, "driftlab firmware: DRIFTLAB_ASSERT failed at firmware line %u\n", static_cast<unsigned>(line));
  abort();
}

// One thread, no interrupts: nothing to mask.
CriticalSection::CriticalSection() : saved_state_(0) {}
CriticalSection::~CriticalSection() {}

}  // namespace fw
}  // namespace driftlab
