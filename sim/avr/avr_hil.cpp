// `driftlab hil --target avr` support; see avr_hil.hpp.
#include "sim/avr/avr_hil.hpp"

#include <cstdio>
#include <filesystem>

#include "sim/avr/avr_error.hpp"
#include "sim/avr/avr_target.hpp"
#include "sim/avr/elf_symbols.hpp"
#include "sim/avr/isr_shared_layout.hpp"

namespace driftlab::sim::avr {

std::function<std::unique_ptr<EmulatedBoard>()> avr_board_factory(const AvrBoardOptions& options) {
    if (options.elf_path.empty()) {
        throw AvrError("no firmware ELF: avr-g++ was not installed when driftlab was built; pass --elf FILE");
    }
    if (!std::filesystem::exists(options.elf_path)) {
        throw AvrError(options.elf_path + ": no such file (build it with `cmake --preset avr` or pass --elf FILE)");
    }
    if (!std::filesystem::is_regular_file(options.elf_path)) throw AvrError(options.elf_path + ": not a file");
    // Read now, so a file that is not this firmware's ELF is the user's --elf, named before the run starts.
    const ElfSymbols symbols(options.elf_path);
    static_cast<void>(symbols.require(kIsrSharedSymbol));
    return [options] { return std::make_unique<AvrTarget>(options); };
}

std::string format_cycle_budget(const CycleBudget& b) {
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line,
                  "AVR cycle budget at %u ms / %u conversions per output (%u ticks, %.0f conversions/s):\n"
                  "  CPU load %.1f %%, dropped %u, tx overflow %u, stack high-water %u of %u bytes\n",
                  b.config.output_period_ms, b.config.conversions_per_output, b.conversion_period_ticks,
                  b.conversions_per_s, 100.0 * b.cpu_load, b.dropped, b.tx_overflow, b.stack_high_water_bytes,
                  b.stack_budget_bytes);
    out += line;
    for (const FunctionCycles& f : b.functions) {
        std::snprintf(line, sizeof line, "  %-17s %8llu calls, mean %7.1f, max %6llu cycles\n", f.label.c_str(),
                      static_cast<unsigned long long>(f.calls), f.mean_cycles(),
                      static_cast<unsigned long long>(f.max_cycles));
        out += line;
    }
    return out;
}

}  // namespace driftlab::sim::avr
