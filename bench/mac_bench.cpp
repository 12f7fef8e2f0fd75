// The MAC candidates for authenticated commands, each in its own ATmega328P image run in simavr
// (firmware/bench/mac_bench_avr.cpp): cycles for one tag over a 25-byte command (exact, from simavr's cycle counter)
// and the flash and RAM the candidate adds to an image without it. Prints figures only (docs/security.md).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "sim/avr/marked_run.hpp"

namespace {

using driftlab::sim::avr::MarkedRun;

std::string image(const char* name) { return std::string(DRIFTLAB_AVR_FW_DIR) + "/driftlab_mac_" + name + ".elf"; }

void candidate(benchmark::State& state, const char* name) {
    if (std::string(DRIFTLAB_AVR_FW_DIR).empty() || !std::filesystem::exists(image(name))) {
        state.SkipWithError("AVR images not built (avr-g++ missing)");
        return;
    }
    MarkedRun base;
    MarkedRun run;
    for (auto _ : state) {
        base = driftlab::sim::avr::run_marked(image("none"), 100000000);
        run = driftlab::sim::avr::run_marked(image(name), 100000000);
    }
    const double cycles = static_cast<double>(run.span_cycles[1] - base.span_cycles[1]);
    state.counters["cycles"] = cycles;
    state.counters["ms_at_16MHz"] = cycles / 16000.0;
    state.counters["flash_bytes"] = static_cast<double>(run.flash_bytes) - base.flash_bytes;
    state.counters["ram_bytes"] = static_cast<double>(run.ram_bytes) - base.ram_bytes;
}

}  // namespace

BENCHMARK_CAPTURE(candidate, siphash24, "siphash24")->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(candidate, blake2s, "blake2s")->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(candidate, sha256, "sha256")->Iterations(1)->Unit(benchmark::kMillisecond);
