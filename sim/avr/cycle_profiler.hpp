// CycleProfiler: exact CPU cycles per call of the firmware's interrupt handlers and hot functions, from simavr's
// cycle counter (docs/avr-in-the-loop.md "Cycle budget").
//
// Method: the profiler runs the emulator one instruction at a time (as avr_run does) and looks at the program
// counter and stack pointer after each. Reaching the first instruction of a watched symbol (address from the
// ELF symbol table) opens a frame with the stack pointer at entry; the frame closes when the stack pointer rises
// above that value (the ret/reti popped the return address). A frame's cycles are inclusive of what it calls
// (the multiply and divide helpers of avr-libgcc), minus the cycles of interrupt handlers that ran inside it, so
// a main-loop figure is not inflated by an ADC interrupt that happened to land in it. The cycles of the
// hardware interrupt response and of the vector table's jmp are not inside any frame. Deterministic: the same
// ELF and inputs give the same counts.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

struct avr_t;

namespace driftlab::sim::avr {

class ElfSymbols;

/// Per-call cycle statistics of one watched symbol.
struct FunctionCycles {
    std::string label;            ///< stable key (adc_isr, ls_push, ...), used in JSON and docs
    std::string symbol;           ///< ELF symbol (mangled)
    std::uint32_t entry_address;  ///< byte address in flash
    bool isr;                     ///< an interrupt vector (its cycles are excluded from enclosing frames)
    std::uint64_t calls = 0;
    std::uint64_t total_cycles = 0;
    std::uint64_t max_cycles = 0;
    double mean_cycles() const { return calls ? static_cast<double>(total_cycles) / calls : 0.0; }
};

class CycleProfiler {
public:
    /// Watches the firmware's ISRs (ADC, Timer1 compare B, USART RX and UDRE) and the least-squares and
    /// per-conversion functions; throws AvrError when one is missing from `symbols`.
    CycleProfiler(const ElfSymbols& symbols, avr_t* avr);

    /// Runs one instruction (avr_run) and accounts its cycles; returns simavr's CPU state.
    int step();
    /// Forgets the counts so far (e.g. the start-up), keeping frames in progress.
    void clear();

    const std::vector<FunctionCycles>& functions() const { return functions_; }
    /// The statistics of `label`; throws AvrError for an unknown label.
    const FunctionCycles& at(const std::string& label) const;

private:
    struct Frame {
        std::size_t function;
        std::uint16_t sp_at_entry;
        std::uint64_t start_cycle;
        std::uint64_t nested_isr_cycles;
    };

    void close_frame(std::uint64_t now);

    avr_t* avr_;
    std::vector<FunctionCycles> functions_;
    std::vector<Frame> frames_;
};

}  // namespace driftlab::sim::avr
