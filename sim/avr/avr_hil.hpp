// What `driftlab hil --target avr` adds to a host-in-the-loop run: the firmware ELF, an optional gdb stub, and
// the cycle budget of the configuration it ran (docs/avr-in-the-loop.md).
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "sim/avr/avr_board.hpp"
#include "sim/avr/cycle_budget.hpp"
#include "sim/hil/emulated_board.hpp"

namespace driftlab::sim::avr {

/// Default ELF: the one the native build made (cmake/avr_firmware.cmake), "" when avr-g++ was missing.
inline std::string default_elf_path() { return DRIFTLAB_AVR_ELF; }

/// HilOptions::make_board for the AVR target: loads `options.elf_path` (AvrError if missing or not the
/// firmware) and, with gdb_port > 0, waits for avr-gdb before the first instruction.
std::function<std::unique_ptr<EmulatedBoard>()> avr_board_factory(const AvrBoardOptions& options);

/// The cycle budget as the lines `driftlab hil --cycles` prints.
std::string format_cycle_budget(const CycleBudget& budget);

}  // namespace driftlab::sim::avr
