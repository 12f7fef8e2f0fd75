// Cycle budget of the real firmware at one configuration: cycles per call of the ADC interrupt and of the
// least-squares update, CPU load (cycles not asleep), lost conversions, UART overflow and stack high-water mark,
// all from simavr's exact cycle counter (docs/avr-in-the-loop.md "Cycle budget"). Also the search for the
// fastest conversion rate the firmware sustains while streaming SAMPLE + RAW at 115200 baud.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "driftlab/proto/messages.hpp"
#include "sim/avr/avr_board.hpp"
#include "sim/avr/cycle_profiler.hpp"

namespace driftlab::sim::avr {

struct CycleBudget {
    proto::ConfigPayload config{};  ///< as sent (stream mode)
    bool accepted = false;          ///< the firmware ACKed the CONFIG_SET
    std::uint32_t conversion_period_ticks = 0;
    double conversions_per_s = 0.0;            ///< all four channels together [1/s]
    double measured_s = 0.0;                   ///< emulated time measured, after a settling time [s]
    std::uint64_t conversions = 0;             ///< timer-triggered conversions in the measured time
    double cpu_load = 0.0;                     ///< fraction of cycles awake in the measured time
    std::uint16_t dropped = 0;                 ///< conversions lost since boot (STATUS at the end)
    std::uint16_t tx_overflow = 0;             ///< frame bytes that did not fit the TX ring (STATUS)
    std::uint16_t rx_overflow = 0;             ///< received bytes lost (STATUS)
    std::uint32_t stack_high_water_bytes = 0;  ///< deepest stack use since power-on
    std::uint32_t stack_budget_bytes = 0;      ///< RAM between the end of .noinit and RAMEND
    std::vector<FunctionCycles> functions;     ///< per-call cycles in the measured time (empty unless profiled)
};

/// Boots `elf_path` with `eeprom` (empty: erased; a calibration there makes every SAMPLE compensated, a key there
/// needs `key` to sign the configuration with, counters from 1: sim/hil/eeprom_image.hpp), streams with
/// `config` (its mode forced to stream) for `settle_s` + `measure_s` of emulated time with inputs around mid-scale,
/// and measures. `profile` adds per-function cycles (slower to run).
CycleBudget measure_cycle_budget(const std::string& elf_path, proto::ConfigPayload config, double settle_s,
                                 double measure_s, bool profile, const std::vector<std::uint8_t>& eeprom = {},
                                 const proto::Key* key = nullptr);

/// Candidate configurations from the firmware's fastest accepted conversion period (50 ticks) upwards, each
/// measured for `measure_s` streaming SAMPLE + RAW; returns them fastest first. The highest sustained rate is
/// the first with accepted, dropped == 0 and tx_overflow == 0.
std::vector<CycleBudget> search_max_rate(const std::string& elf_path, double measure_s,
                                         const std::vector<std::uint8_t>& eeprom = {});

}  // namespace driftlab::sim::avr
