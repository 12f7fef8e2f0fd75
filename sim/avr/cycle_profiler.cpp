// CycleProfiler: frames opened at watched entry addresses, closed when SP rises above its entry value
// (cycle_profiler.hpp).
#include "sim/avr/cycle_profiler.hpp"

#include <simavr/sim_avr.h>

#include <algorithm>

#include "sim/avr/avr_error.hpp"
#include "sim/avr/elf_symbols.hpp"

namespace driftlab::sim::avr {
namespace {

struct Watched {
    const char* label;
    const char* symbol;
    bool isr;
};

// ATmega328P vectors (datasheet, "Interrupts"): 12 TIMER1_COMPB, 18 USART_RX, 19 USART_UDRE, 21 ADC.
constexpr Watched kWatched[] = {
    {"adc_isr", "__vector_21", true},
    {"timer1_compb_isr", "__vector_12", true},
    {"uart_rx_isr", "__vector_18", true},
    {"uart_udre_isr", "__vector_19", true},
    {"on_conversion", "_ZN8driftlab2fw8Firmware13on_conversionENS_7ChannelEjm", false},
    {"ls_push", "_ZN8driftlab2fw8LsWindow4pushEj", false},
    {"ls_estimate", "_ZNK8driftlab2fw8LsWindow11estimate_q8ENS0_8FitOrderE", false},
    {"send_sample", "_ZN8driftlab2fw8Firmware11send_sampleEv", false},
};

std::uint16_t stack_pointer(const avr_t* avr) {
    return static_cast<std::uint16_t>(avr->data[R_SPL] | avr->data[R_SPH] << 8);
}

}  // namespace

CycleProfiler::CycleProfiler(const ElfSymbols& symbols, avr_t* avr) : avr_(avr) {
    for (const Watched& w : kWatched) {
        const ElfSymbol s = symbols.require(w.symbol);
        functions_.push_back({w.label, w.symbol, s.address, w.isr});
    }
}

int CycleProfiler::step() {
    const int state = avr_run(avr_);
    const std::uint64_t now = avr_->cycle;
    const std::uint16_t sp = stack_pointer(avr_);
    while (!frames_.empty() && sp > frames_.back().sp_at_entry) {
        close_frame(now);
    }
    const auto pc = static_cast<std::uint32_t>(avr_->pc);
    for (std::size_t f = 0; f < functions_.size(); ++f) {
        if (functions_[f].entry_address != pc) {
            continue;
        }
        // A jump back to the entry from inside the function is not a new call.
        if (frames_.empty() || frames_.back().function != f || frames_.back().sp_at_entry != sp) {
            frames_.push_back({f, sp, now, 0});
        }
        break;
    }
    return state;
}

void CycleProfiler::close_frame(std::uint64_t now) {
    const Frame frame = frames_.back();
    frames_.pop_back();
    FunctionCycles& fn = functions_[frame.function];
    const std::uint64_t inclusive = now - frame.start_cycle;
    const std::uint64_t own = inclusive - frame.nested_isr_cycles;
    ++fn.calls;
    fn.total_cycles += own;
    fn.max_cycles = std::max(fn.max_cycles, own);
    if (!frames_.empty()) {
        frames_.back().nested_isr_cycles += fn.isr ? inclusive : frame.nested_isr_cycles;
    }
}

void CycleProfiler::clear() {
    for (FunctionCycles& fn : functions_) {
        fn.calls = 0;
        fn.total_cycles = 0;
        fn.max_cycles = 0;
    }
}

const FunctionCycles& CycleProfiler::at(const std::string& label) const {
    for (const FunctionCycles& fn : functions_) {
        if (fn.label == label) {
            return fn;
        }
    }
    throw AvrError("no cycle statistics for '" + label + "'");
}

}  // namespace driftlab::sim::avr
