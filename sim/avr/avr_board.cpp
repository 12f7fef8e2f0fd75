// AvrBoard: simavr wiring of the ATmega328P firmware (avr_board.hpp, docs/avr-in-the-loop.md).
#include "sim/avr/avr_board.hpp"

#include <simavr/avr_adc.h>
#include <simavr/avr_eeprom.h>
#include <simavr/avr_uart.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_elf.h>
#include <simavr/sim_gdb.h>
#include <simavr/sim_interrupts.h>
#include <simavr/sim_irq.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "firmware/core/version.hpp"
#include "sim/avr/avr_error.hpp"
#include "sim/avr/cycle_profiler.hpp"
#include "sim/avr/elf_firmware.hpp"
#include "sim/avr/elf_symbols.hpp"
#include "sim/avr/isr_shared_layout.hpp"
#include "sim/avr/simavr_adc.hpp"

namespace driftlab::sim::avr {
namespace {

constexpr std::uint8_t kTimer1CompbVector = 12;  // ATmega328P datasheet, "Interrupts": TIMER1 COMPB
constexpr std::uint16_t kMcusrAddress = 0x54;    // MCUSR in data space
constexpr std::uint8_t kMcusrPorf = 0x01;
constexpr std::uint16_t kAdcsraAddress = 0x7A;  // ADCSRA in data space
constexpr std::uint8_t kAdcsraAdate = 0x20;
constexpr std::uint16_t kTccr1bAddress = 0x81;  // TCCR1B in data space; CS12..CS10 = clock select
constexpr std::uint8_t kTccr1bClockSelect = 0x07;
constexpr std::uint8_t kStackPaint = 0xA5;  // untouched-RAM pattern for the stack high-water mark

AvrBoard* board_of(avr_t* avr) { return static_cast<AvrBoard*>(avr->custom.data); }

// simavr's own messages go to stderr, errors only: its default logger prints the loader's "Loaded N .text" on
// stdout, where a log (-o -) or the JSON summary goes.
void stderr_logger(avr_t* avr, const int level, const char* format, va_list args) {
    const int threshold = avr ? static_cast<int>(avr->log) : static_cast<int>(LOG_ERROR);
    if (level < LOG_ERROR || level > threshold) return;
    std::vfprintf(stderr, format, args);
}

// USART0 registers in data space and their bits (ATmega328P datasheet, "USART0").
constexpr std::uint16_t kUcsr0a = 0xC0, kUcsr0b = 0xC1, kUcsr0c = 0xC2, kUbrr0l = 0xC4, kUbrr0h = 0xC5;
constexpr std::uint8_t kU2x0 = 0x02, kUcsz02 = 0x04, kUsbs0 = 0x08, kUpm0 = 0x30, kUcsz0 = 0x06;

// Cycles of one UART frame as the chip times it: (start + data + parity + stop) bits of (UBRR + 1) x 8 cycles
// with U2X, x 16 without. 0 while UBRR is not set.
std::uint64_t uart_cycles_per_byte(const avr_t* avr) {
    const std::uint32_t ubrr = avr->data[kUbrr0l] | (avr->data[kUbrr0h] & 0x0F) << 8;
    if (ubrr == 0) {
        return 0;
    }
    const std::uint32_t ucsz = (avr->data[kUcsr0c] & kUcsz0) >> 1 | ((avr->data[kUcsr0b] & kUcsz02) ? 4U : 0U);
    const std::uint32_t data_bits = ucsz <= 3 ? 5 + ucsz : (ucsz == 7 ? 9 : 8);
    const std::uint32_t bits =
        1 + data_bits + ((avr->data[kUcsr0c] & kUpm0) ? 1 : 0) + ((avr->data[kUcsr0c] & kUsbs0) ? 2 : 1);
    const std::uint32_t cycles_per_bit = ((avr->data[kUcsr0a] & kU2x0) ? 8U : 16U) * (ubrr + 1);
    return std::uint64_t{bits} * cycles_per_bit;
}

}  // namespace

AvrBoard::AvrBoard(const AvrBoardOptions& options, VoltageSource source)
    : source_(std::move(source)),
      die_temperature_(options.die_temperature),
      elf_path_(options.elf_path),
      gdb_(options.gdb_port > 0) {
    const ElfSymbols symbols(options.elf_path);
    const ElfSymbol isr_shared = symbols.require(kIsrSharedSymbol);
    if (isr_shared.size_bytes != IsrSharedLayout::kTotalBytes) {
        throw AvrError(options.elf_path + ": fw::g_isr is " + std::to_string(isr_shared.size_bytes) +
                       " bytes, the harness expects " + std::to_string(IsrSharedLayout::kTotalBytes) +
                       "; firmware/port/avr/isr_shared_avr.hpp changed, update sim/avr/isr_shared_layout.hpp");
    }
    isr_shared_address_ = isr_shared.address - kAvrDataOffset;
    data_end_address_ = symbols.require("_end").address - kAvrDataOffset;

    avr_global_logger_set(stderr_logger);
    ElfFirmware elf;
    elf_firmware_t& firmware = elf.f;
    if (elf_read_firmware(options.elf_path.c_str(), &firmware) != 0) {
        throw AvrError(options.elf_path + ": simavr cannot load this ELF");
    }
    if (std::strcmp(firmware.mmcu, "atmega328p") != 0 || firmware.frequency != kCpuHz) {
        throw AvrError(options.elf_path + ": tagged for '" + firmware.mmcu + "' at " +
                       std::to_string(firmware.frequency) + " Hz, expected atmega328p at 16000000 Hz");
    }
    avr_ = avr_make_mcu_by_name(firmware.mmcu);
    if (avr_ == nullptr) {
        throw AvrError("simavr has no ATmega328P model");
    }
    avr_init(avr_);
    avr_->log = LOG_ERROR;  // simavr warns at every trigger that it cannot auto-trigger (we do it, below)
    avr_load_firmware(avr_, &firmware);
    if (!options.eeprom.empty()) load_eeprom(options.eeprom);
    avr_->frequency = kCpuHz;
    avr_->vcc = kBoardVrefMv;
    avr_->avcc = kBoardVrefMv;
    avr_->aref = kBoardVrefMv;
    avr_->custom.data = this;
    avr_->data[kMcusrAddress] = kMcusrPorf;
    for (std::uint32_t a = data_end_address_; a <= avr_->ramend; ++a) {
        avr_->data[a] = kStackPaint;
    }

    // Timer1 compare B -> ADC start (the auto-trigger simavr lacks).
    avr_irq_t* compb = avr_get_interrupt_irq(avr_, kTimer1CompbVector);
    adc_irq_ = avr_io_getirq(avr_, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_ADC0);
    uart_input_ = avr_io_getirq(avr_, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_INPUT);
    for (avr_io_t* io = avr_->io_port; io != nullptr; io = io->next) {
        if (std::strcmp(io->kind, "uart") == 0 && reinterpret_cast<avr_uart_t*>(io)->name == '0') {
            uart0_ = reinterpret_cast<avr_uart_t*>(io);
        }
    }
    if (compb == nullptr || adc_irq_ == nullptr || uart_input_ == nullptr || uart0_ == nullptr) {
        throw AvrError("simavr's ATmega328P lacks Timer1, ADC or UART0 signals");
    }
    avr_irq_register_notify(compb + AVR_INT_IRQ_PENDING, &AvrBoard::on_timer1_compb_pending, this);
    avr_irq_register_notify(adc_irq_ + ADC_IRQ_OUT_TRIGGER, &AvrBoard::on_adc_trigger, this);
    avr_irq_t* uart_output = avr_io_getirq(avr_, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT);
    avr_irq_register_notify(uart_output, &AvrBoard::on_uart_output, this);
    avr_irq_register_notify(uart_input_ + (UART_IRQ_OUT_XON - UART_IRQ_INPUT), &AvrBoard::on_uart_xon, this);
    avr_irq_register_notify(uart_input_ + (UART_IRQ_OUT_XOFF - UART_IRQ_INPUT), &AvrBoard::on_uart_xoff, this);
    std::uint32_t flags = 0;
    avr_ioctl(avr_, AVR_IOCTL_UART_GET_FLAGS('0'), &flags);
    flags &= ~static_cast<std::uint32_t>(AVR_UART_FLAG_STDIO);
    avr_ioctl(avr_, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);

    if (gdb_) {
        avr_->gdb_port = options.gdb_port;
        avr_->state = cpu_Stopped;
        if (avr_gdb_init(avr_) != 0) {
            throw AvrError("cannot start the gdb stub on port " + std::to_string(options.gdb_port));
        }
    } else {
        avr_->sleep = &AvrBoard::on_sleep;
    }
    if (options.profile) {
        profiler_ = std::make_unique<CycleProfiler>(symbols, avr_);
    }
}

AvrBoard::~AvrBoard() {
    if (avr_ != nullptr) {
        if (gdb_) {
            avr_deinit_gdb(avr_);
        }
        avr_terminate(avr_);
    }
}

std::uint64_t AvrBoard::cycle() const { return avr_->cycle; }

std::uint64_t AvrBoard::cycles_for_s(double t_s) {
    return static_cast<std::uint64_t>(std::llround(t_s * static_cast<double>(kCpuHz)));
}

void AvrBoard::run_until_cycle(std::uint64_t cycle) {
    if (avr_->cycle >= cycle) {
        return;
    }
    sync_uart_rate();
    // A cycle timer at the target ends any sleep there, so the caller gets control back on time.
    avr_cycle_timer_register(avr_, cycle - avr_->cycle, &AvrBoard::on_run_limit, this);
    while (avr_->cycle < cycle) {
        const int state = profiler_ ? profiler_->step() : avr_run(avr_);
        if (state == cpu_Done || state == cpu_Crashed) {
            avr_cycle_timer_cancel(avr_, &AvrBoard::on_run_limit, this);
            throw AvrError(elf_path_ + ": firmware " +
                           (state == cpu_Done ? "stopped (sleep with interrupts off)" : "crashed") + " at cycle " +
                           std::to_string(avr_->cycle) + ", pc 0x" + [&] {
                               char hex[16];
                               std::snprintf(hex, sizeof hex, "%04x", static_cast<unsigned>(avr_->pc));
                               return std::string(hex);
                           }());
        }
    }
    avr_cycle_timer_cancel(avr_, &AvrBoard::on_run_limit, this);
}

void AvrBoard::run_until_armed() {
    // The first hal_init() starts Timer1 from 0 with the firmware's clock at tick 0 (hal_avr.cpp): the epoch is
    // the cycle at which TCCR1B first selects a clock. Start-up has no conversion to feed, so stepping one
    // instruction at a time through it costs little.
    const std::uint64_t limit = avr_->cycle + kCpuHz;
    while (!epoch_cycle_ && avr_->cycle < limit) {
        run_until_cycle(avr_->cycle + 1);
        if ((avr_->data[kTccr1bAddress] & kTccr1bClockSelect) != 0) {
            epoch_cycle_ = avr_->cycle;
        }
    }
    if (!epoch_cycle_) {
        throw AvrError(elf_path_ + ": the firmware armed no ADC conversion within one second of power-on");
    }
}

void AvrBoard::receive(const std::uint8_t* bytes, std::size_t count) {
    if (count == 0) {
        return;
    }
    rx_queue_.insert(rx_queue_.end(), bytes, bytes + count);
    schedule_rx_pump(std::max(rx_next_cycle_, avr_->cycle));
}

std::size_t AvrBoard::transmit(std::uint8_t* out, std::size_t capacity) {
    std::size_t n = 0;
    while (n < capacity && tx_read_ < tx_.size()) {
        out[n++] = tx_[tx_read_++].value;
    }
    if (tx_read_ == tx_.size()) {
        tx_.clear();
        tx_read_ = 0;
    }
    return n;
}

std::vector<UartTxByte> AvrBoard::transmit_timed() {
    std::vector<UartTxByte> out(tx_.begin() + static_cast<std::ptrdiff_t>(tx_read_), tx_.end());
    tx_.clear();
    tx_read_ = 0;
    return out;
}

std::uint64_t AvrBoard::next_trigger_tick() const {
    const std::uint32_t base = isr_shared_address_;
    const auto tick32 = static_cast<std::uint32_t>(read_ram_u32(base + IsrSharedLayout::kTriggerTickOffset) +
                                                   read_ram_u32(base + IsrSharedLayout::kStepTicksOffset));
    return last_trigger_tick_ + static_cast<std::uint32_t>(tick32 - static_cast<std::uint32_t>(last_trigger_tick_));
}

std::uint32_t AvrBoard::stack_budget_bytes() const { return avr_->ramend + 1U - data_end_address_; }

std::uint32_t AvrBoard::stack_high_water_bytes() const {
    std::uint32_t a = data_end_address_;
    while (a <= avr_->ramend && avr_->data[a] == kStackPaint) {
        ++a;
    }
    return avr_->ramend + 1U - a;
}

std::uint32_t AvrBoard::read_ram_u32(std::uint32_t address) const {
    const std::uint8_t* p = avr_->data + address;
    return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
           static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

void AvrBoard::sync_uart_rate() {
    if (const std::uint64_t cycles = uart_cycles_per_byte(avr_); cycles != 0) {
        uart0_->cycles_per_byte = cycles;
    }
}

void AvrBoard::schedule_rx_pump(std::uint64_t at_cycle) {
    if (rx_pump_scheduled_ || rx_queue_.empty() || rx_fifo_full_) {
        return;
    }
    rx_pump_scheduled_ = true;
    avr_cycle_timer_register(avr_, at_cycle > avr_->cycle ? at_cycle - avr_->cycle : 1, &AvrBoard::on_rx_pump, this);
}

void AvrBoard::on_timer1_compb_pending(avr_irq_t*, std::uint32_t value, void* param) {
    auto* self = static_cast<AvrBoard*>(param);
    if (value != 0) {
        avr_raise_irq(self->adc_irq_ + ADC_IRQ_IN_TRIGGER, 1);
        avr_raise_irq(self->adc_irq_ + ADC_IRQ_IN_TRIGGER, 0);
    }
}

void AvrBoard::on_adc_trigger(avr_irq_t*, std::uint32_t value, void* param) {
    auto* self = static_cast<AvrBoard*>(param);
    // simavr sends the bit-field struct through a union with a uint32_t (avr_adc.c); the struct's fields are
    // `unsigned long` bit-fields, 8 bytes on x86-64 with the 32 used bits first (little-endian), so copy the
    // value into the start of a zeroed struct.
    avr_adc_mux_t mux{};
    static_assert(sizeof mux >= sizeof value, "avr_adc_mux_t holds the IRQ's 32-bit value");
    std::memcpy(&mux, &value, sizeof value);
    if (mux.kind == ADC_MUX_TEMP) {
        // At boot, and right after the round's last conversion: the die at that conversion's trigger, as the native
        // board reads it (NativeTarget), in millivolts against the 1.1 V reference the firmware selects.
        const double t_s = static_cast<double>(self->last_trigger_tick_) / fw::kTickHz;
        avr_raise_irq(self->adc_irq_ + ADC_IRQ_TEMP,
                      millivolts_for_code(self->die_temperature_.code(t_s), kTemperatureVrefMv));
        return;
    }
    if (mux.kind != ADC_MUX_SINGLE) {
        return;
    }
    // The firmware's warm-up conversion (avr_board_init) is started by hand, not by Timer1: it is discarded by
    // the firmware and must not consume a sample of the source (whose noise streams advance per call).
    if ((self->avr_->data[kAdcsraAddress] & kAdcsraAdate) == 0) {
        avr_raise_irq(self->adc_irq_ + mux.src, kBoardVrefMv / 2);
        return;
    }
    self->sync_uart_rate();
    const std::uint32_t base = self->isr_shared_address_;
    const auto tick32 = static_cast<std::uint32_t>(self->read_ram_u32(base + IsrSharedLayout::kTriggerTickOffset) +
                                                   self->read_ram_u32(base + IsrSharedLayout::kStepTicksOffset));
    // Unwrap: triggers are less than 2^32 ticks (4.77 h) apart.
    std::uint64_t tick = self->last_trigger_tick_;
    tick += static_cast<std::uint32_t>(tick32 - static_cast<std::uint32_t>(tick));
    self->last_trigger_tick_ = tick;
    ++self->triggered_conversions_;
    std::uint32_t mv = 0;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (fw::kAdcPin[c] == mux.src) {
            mv = self->source_(static_cast<Channel>(c), tick);
        }
    }
    avr_raise_irq(self->adc_irq_ + mux.src, mv);
}

void AvrBoard::on_uart_output(avr_irq_t*, std::uint32_t value, void* param) {
    auto* self = static_cast<AvrBoard*>(param);
    self->sync_uart_rate();
    self->tx_.push_back({self->avr_->cycle, static_cast<std::uint8_t>(value)});
}

void AvrBoard::on_uart_xon(avr_irq_t*, std::uint32_t, void* param) {
    auto* self = static_cast<AvrBoard*>(param);
    if (self->rx_fifo_full_) {
        self->rx_fifo_full_ = false;
        self->schedule_rx_pump(std::max(self->rx_next_cycle_, self->avr_->cycle));
    }
}

void AvrBoard::on_uart_xoff(avr_irq_t*, std::uint32_t, void* param) {
    static_cast<AvrBoard*>(param)->rx_fifo_full_ = true;
}

std::uint64_t AvrBoard::on_rx_pump(avr_t*, std::uint64_t when, void* param) {
    auto* self = static_cast<AvrBoard*>(param);
    self->rx_pump_scheduled_ = false;
    if (self->rx_fifo_full_ || self->rx_queue_.empty()) {
        return 0;  // XON reschedules
    }
    self->sync_uart_rate();
    const std::uint8_t byte = self->rx_queue_.front();
    self->rx_queue_.pop_front();
    avr_raise_irq(self->uart_input_, byte);
    self->rx_next_cycle_ = when + kRxByteCycles;
    if (!self->rx_queue_.empty() && !self->rx_fifo_full_) {
        self->rx_pump_scheduled_ = true;
        return self->rx_next_cycle_;
    }
    return 0;
}

std::uint64_t AvrBoard::on_run_limit(avr_t*, std::uint64_t, void*) { return 0; }

void AvrBoard::on_sleep(avr_t* avr, std::uint64_t how_long) {
    // simavr adds 1 + how_long cycles for this sleep step (avr_callback_run_raw).
    board_of(avr)->sleep_cycles_ += 1 + how_long;
}

void AvrBoard::load_eeprom(const std::vector<std::uint8_t>& image) {
    std::vector<std::uint8_t> copy = image;  // simavr copies from a non-const pointer
    avr_eeprom_desc_t desc{copy.data(), 0, static_cast<std::uint32_t>(copy.size())};
    // simavr's SET returns -1 even when it copied: read the EEPROM back (GET points into it) to know.
    avr_ioctl(avr_, AVR_IOCTL_EEPROM_SET, &desc);
    avr_eeprom_desc_t back{nullptr, 0, static_cast<std::uint32_t>(image.size())};
    avr_ioctl(avr_, AVR_IOCTL_EEPROM_GET, &back);
    if (back.ee == nullptr || !std::equal(image.begin(), image.end(), back.ee))
        throw AvrError("simavr did not take the EEPROM image (" + std::to_string(image.size()) + " bytes)");
}

}  // namespace driftlab::sim::avr
