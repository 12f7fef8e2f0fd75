// NativeBoard: virtual-time board behind the native HAL (native_board.hpp, docs/hal.md "Native port").
#include "firmware/port/native/native_board.hpp"

#include "driftlab/proto/temperature.hpp"

namespace driftlab {
namespace fw {
namespace {

thread_local NativeBoard* t_current_board = nullptr;

}  // namespace

NativeBoard::NativeBoard()
    : schedule_(),
      armed_(false),
      next_index_(0),
      arm_count_(0),
      next_trigger_ticks_(0),
      time_ticks_(0),
      rx_overflow_bytes_(0),
      temperature_requested_(false),
      die_temperature_code_(proto::temperature_code_of_celsius(25.0)),
      reset_info_{kResetPowerOn, 0},
      eeprom_(),
      adc_ring_(),
      rx_ring_(),
      tx_ring_(),
      previous_(t_current_board) {
  for (uint16_t i = 0; i < kEepromBytes; ++i) {
    eeprom_[i] = 0xFF;
  }
  t_current_board = this;
}

void NativeBoard::load_eeprom(const uint8_t* image, size_t size) {
  for (size_t i = 0; i < size && i < kEepromBytes; ++i) {
    eeprom_[i] = image[i];
  }
}

NativeBoard::~NativeBoard() { t_current_board = previous_; }

NativeBoard* NativeBoard::current() { return t_current_board; }

void NativeBoard::set_time_ticks(uint64_t time_ticks) {
  DRIFTLAB_ASSERT(time_ticks >= time_ticks_);
  time_ticks_ = time_ticks;
}

bool NativeBoard::convert(uint16_t code_counts) {
  DRIFTLAB_ASSERT(armed_ && code_counts <= LsWindow::kMaxCode);
  const Conversion conversion = {next_channel(), code_counts, static_cast<uint32_t>(next_trigger_ticks_)};
  const bool temperature = temperature_due();
  next_index_ = static_cast<uint8_t>((next_index_ + 1U) % kChannelCount);
  next_trigger_ticks_ += schedule_.conversion_period_ticks;
  const bool pushed = adc_ring_.push(conversion);
  if (temperature) {
    temperature_requested_ = false;
    static_cast<void>(adc_ring_.push(Conversion{kTemperatureInput, die_temperature_code_, conversion.tick}));
  }
  return pushed;
}

size_t NativeBoard::receive(const uint8_t* bytes, size_t count) {
  size_t accepted = 0;
  for (size_t i = 0; i < count; ++i) {
    if (rx_ring_.push(bytes[i])) {
      ++accepted;
    } else if (rx_overflow_bytes_ != 0xFFFFU) {
      ++rx_overflow_bytes_;
    }
  }
  return accepted;
}

size_t NativeBoard::transmit(uint8_t* out, size_t capacity) {
  size_t n = 0;
  while (n < capacity && tx_ring_.pop(&out[n])) {
    ++n;
  }
  return n;
}

void NativeBoard::service(Firmware& firmware) {
  Conversion conversion = {};
  while (adc_ring_.pop(&conversion)) {
    firmware.on_conversion(conversion.channel, conversion.code_counts, conversion.tick);
  }
  uint8_t byte = 0;
  while (rx_ring_.pop(&byte)) {
    firmware.on_rx_byte(byte);
  }
}

void NativeBoard::on_hal_init(const AdcSchedule& schedule) {
  DRIFTLAB_ASSERT(schedule.conversion_period_ticks >= 1);
  schedule_ = schedule;
  armed_ = true;
  ++arm_count_;
  next_index_ = 0;
  temperature_requested_ = false;
  next_trigger_ticks_ = time_ticks_ + arm_wait_ticks(schedule, static_cast<uint32_t>(time_ticks_));
  adc_ring_.clear();
}

uint8_t NativeBoard::on_hal_uart_write(const uint8_t* bytes, uint8_t count) {
  if (tx_ring_.free_space() < count) {
    return 0;
  }
  for (uint8_t i = 0; i < count; ++i) {
    static_cast<void>(tx_ring_.push(bytes[i]));
  }
  return count;
}

}  // namespace fw
}  // namespace driftlab
