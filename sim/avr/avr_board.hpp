// AvrBoard: the real ATmega328P firmware (driftlab_fw.elf) running in simavr, in emulated time, with the same
// outside as the native board: the sensor model answers every ADC conversion, UART0 bytes go out to the link,
// host bytes come in through UART0. docs/avr-in-the-loop.md.
//
// How to drive it:
//
//   AvrBoard board(AvrBoardOptions{elf}, [&](Channel c, std::uint64_t tick) { return millivolts_for_code(...); });
//   while (running) {
//     board.run_until_cycle(cycle_of(t));         // the firmware runs; conversions ask the source for millivolts
//     board.receive(bytes, n);                     // host bytes enter UART0 from now on, 10 bits each at 115200
//     n_out = board.transmit(out, sizeof out);     // bytes the firmware wrote to UDR0 so far
//   }
//
// What simavr 1.6 does not do and this board does:
//  - ADC auto-trigger from Timer1 compare match B (ADTS = 101) is not implemented in avr_adc.c; the board
//    watches the TIMER1_COMPB vector's pending signal, the compare-B flag rising, and starts the conversion
//    through ADC_IRQ_IN_TRIGGER, as the chip's trigger logic does.
//  - UART timing: simavr 1.6 derives the byte time when UBRR0 is written, ignoring a U2X set afterwards (the
//    firmware sets U2X after UBRR0, in either order on the chip) and counting a parity bit that 8N1 has not: it
//    would send at 187 us per byte instead of 85. The board keeps simavr's byte time at the chip's, computed from
//    UBRR0, U2X0, UCSZ0, UPM0 and USBS0.
//  - Power-on reset: MCUSR reads 0 after simavr's reset; the board sets PORF as a power-up does.
//  - The default sleep callback paces the emulator to the wall clock; the board replaces it, so the firmware's
//    idle sleep costs no wall time (except under gdb, whose own callback keeps the stub responsive).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "driftlab/channels.hpp"
#include "sim/hil/die_temperature.hpp"

struct avr_t;
struct avr_irq_t;
struct avr_uart_t;

namespace driftlab::sim::avr {

class CycleProfiler;

/// Input of one conversion [mV] for `channel` at the firmware's trigger tick [ticks of fw::kTickHz since
/// power-on, unwrapped to 64 bits] (the tick the firmware stamps on that conversion).
using VoltageSource = std::function<std::uint32_t(Channel channel, std::uint64_t trigger_tick)>;

struct AvrBoardOptions {
    std::string elf_path;  ///< driftlab_fw.elf (ATmega328P build)
    int gdb_port = 0;      ///< > 0: start simavr's gdb stub on this TCP port, the CPU stopped until gdb continues
    bool profile = false;  ///< count cycles per function and ISR (slower; see CycleProfiler)
    /// The EEPROM at power-on (up to 1024 bytes from address 0; sim/hil/eeprom_image.hpp); empty: erased.
    std::vector<std::uint8_t> eeprom{};
    /// What the die temperature sensor (ADC8) reads, at the trigger of the conversion it follows (0 at boot).
    DieTemperature die_temperature{};
};

/// One byte the firmware wrote to UDR0, at the emulated cycle it did.
struct UartTxByte {
    std::uint64_t cycle;
    std::uint8_t value;
};

class AvrBoard {
public:
    static constexpr std::uint32_t kCpuHz = 16000000;  ///< the board's crystal; must match the ELF's tag
    static constexpr std::uint32_t kBaud = 115200;     ///< UART0 rate of the firmware [bit/s]
    /// Cycles one 8N1 byte occupies the RX line: 10 bits at kBaud, rounded up.
    static constexpr std::uint64_t kRxByteCycles = (10ULL * kCpuHz + kBaud - 1) / kBaud;

    /// Loads the ELF into an ATmega328P at 16 MHz with VCC = AVCC = AREF = 5 V, paints the free RAM for the
    /// stack high-water mark, and wires ADC, Timer1 trigger and UART0. Throws AvrError (file, reason).
    AvrBoard(const AvrBoardOptions& options, VoltageSource source);
    ~AvrBoard();
    AvrBoard(const AvrBoard&) = delete;
    AvrBoard& operator=(const AvrBoard&) = delete;

    // ---- Time ----
    /// Emulated CPU cycles since power-on (exact, repeatable).
    std::uint64_t cycle() const;
    double time_s() const { return static_cast<double>(cycle()) / kCpuHz; }
    static std::uint64_t cycles_for_s(double t_s);
    /// Runs the firmware until the cycle counter reaches `cycle` (it may pass it by one instruction). Throws
    /// AvrError when the firmware stops (sleep with interrupts off) or crashes.
    void run_until_cycle(std::uint64_t cycle);
    void run_until_s(double t_s) { run_until_cycle(cycles_for_s(t_s)); }
    /// Runs the start-up code until the firmware starts Timer1 (its first hal_init()), which fixes
    /// firmware_epoch_cycle(). Throws AvrError when that does not happen within one emulated second.
    void run_until_armed();
    /// Cycle at which the firmware's tick 0 began (Timer1 started by the first hal_init()), known after
    /// run_until_armed(). The native board's time 0 is its firmware's tick 0, so a host that wants the same
    /// instants on both boards counts AVR time from here (0.808 ms after power-on for the current firmware).
    std::optional<std::uint64_t> firmware_epoch_cycle() const { return epoch_cycle_; }

    /// Trigger tick of the next timer-triggered conversion [ticks, unwrapped], from the firmware's own state; the
    /// conversion in progress while its compare vector has not run yet.
    std::uint64_t next_trigger_tick() const;

    // ---- UART0 ----
    /// Queues host bytes for UART0's receiver: one every kRxByteCycles from now (or after the bytes already
    /// queued), held back while simavr's receive FIFO says XOFF.
    void receive(const std::uint8_t* bytes, std::size_t count);
    /// Moves up to `capacity` bytes the firmware has sent into `out`; returns how many.
    std::size_t transmit(std::uint8_t* out, std::size_t capacity);
    /// Like transmit(), with the cycle each byte was written to UDR0.
    std::vector<UartTxByte> transmit_timed();

    // ---- Figures ----
    /// Cycles the CPU slept (idle mode) since power-on; load = 1 - sleep / cycle.
    std::uint64_t sleep_cycles() const { return sleep_cycles_; }
    /// ADC conversions triggered by Timer1 (excluding the firmware's warm-up conversion).
    std::uint64_t triggered_conversions() const { return triggered_conversions_; }
    /// Deepest stack use since power-on [bytes below RAMEND + 1], from the painted RAM.
    std::uint32_t stack_high_water_bytes() const;
    /// Bytes between the end of the firmware's data (.data, .bss, .noinit) and RAMEND + 1: stack budget.
    std::uint32_t stack_budget_bytes() const;
    /// The profiler when options.profile was set, else nullptr.
    const CycleProfiler* profiler() const { return profiler_.get(); }
    CycleProfiler* profiler() { return profiler_.get(); }

private:
    void load_eeprom(const std::vector<std::uint8_t>& image);
    static void on_timer1_compb_pending(avr_irq_t* irq, std::uint32_t value, void* param);
    static void on_adc_trigger(avr_irq_t* irq, std::uint32_t value, void* param);
    static void on_uart_output(avr_irq_t* irq, std::uint32_t value, void* param);
    static void on_uart_xon(avr_irq_t* irq, std::uint32_t value, void* param);
    static void on_uart_xoff(avr_irq_t* irq, std::uint32_t value, void* param);
    static std::uint64_t on_rx_pump(avr_t* avr, std::uint64_t when, void* param);
    static std::uint64_t on_run_limit(avr_t* avr, std::uint64_t when, void* param);
    static void on_sleep(avr_t* avr, std::uint64_t how_long);

    std::uint32_t read_ram_u32(std::uint32_t address) const;
    void schedule_rx_pump(std::uint64_t at_cycle);
    void sync_uart_rate();

    avr_t* avr_ = nullptr;
    VoltageSource source_;
    DieTemperature die_temperature_;
    std::string elf_path_;
    bool gdb_ = false;
    std::unique_ptr<CycleProfiler> profiler_;

    std::uint32_t isr_shared_address_ = 0;  // RAM address of fw::g_isr
    std::uint32_t data_end_address_ = 0;    // RAM address just past .noinit: the lowest byte the stack may use
    std::uint64_t last_trigger_tick_ = 0;   // unwrapped
    std::uint64_t triggered_conversions_ = 0;
    std::optional<std::uint64_t> epoch_cycle_;
    std::uint64_t sleep_cycles_ = 0;

    avr_irq_t* adc_irq_ = nullptr;     // ADC_IRQ_ADC0.. of the ADC module
    avr_irq_t* uart_input_ = nullptr;  // UART_IRQ_INPUT of UART0
    avr_uart_t* uart0_ = nullptr;
    std::deque<std::uint8_t> rx_queue_;
    std::uint64_t rx_next_cycle_ = 0;  // earliest cycle for the next byte on the line
    bool rx_fifo_full_ = false;        // XOFF seen, no XON since
    bool rx_pump_scheduled_ = false;
    std::vector<UartTxByte> tx_;
    std::size_t tx_read_ = 0;
};

}  // namespace driftlab::sim::avr
