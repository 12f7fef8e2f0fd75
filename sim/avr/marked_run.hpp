// MarkedRun: an AVR image that marks its own work, run in simavr from reset: it writes a span's number to GPIOR0
// before the work and 0 after it, and 0xFF when done. What bench/mac_bench.cpp measures the MAC candidates with:
// exact cycles per span, and the image's flash and RAM.
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace driftlab::sim::avr {

struct MarkedRun {
    std::map<std::uint8_t, std::uint64_t> span_cycles;  ///< cycles between GPIOR0 = n and the next GPIOR0 = 0
    std::uint32_t flash_bytes = 0;                      ///< .text + .data
    std::uint32_t ram_bytes = 0;                        ///< .data + .bss (the stack comes on top)
};

/// Runs `elf_path` (an ATmega328P image at 16 MHz) until it writes 0xFF to GPIOR0, for at most `max_cycles`. Throws
/// AvrError when it cannot be loaded or does not finish.
MarkedRun run_marked(const std::string& elf_path, std::uint64_t max_cycles);

}  // namespace driftlab::sim::avr
