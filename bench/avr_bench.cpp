// The ATmega328P firmware in simavr: emulated seconds per wall second for the paper's two recordings (Fig. 3:
// 4000 s at 1 output/s; Fig. 2: 1000 outputs at 0.1 s), and the cycle budget from the exact cycle counter
// (ISR and least-squares cycles per call, CPU load, stack high-water mark, fastest sustained rate at 115200).
// Prints figures only (docs/avr-in-the-loop.md).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "driftlab/proto/encoder.hpp"
#include "driftlab/proto/wire.hpp"
#include "firmware/core/hal.hpp"
#include "sim/avr/avr_board.hpp"
#include "sim/avr/cycle_budget.hpp"
#include "sim/avr/simavr_adc.hpp"
#include "sim/model/model_file.hpp"
#include "sim/model/sensor_model.hpp"

namespace {

using namespace driftlab;
using namespace driftlab::sim::avr;

bool have_elf(benchmark::State& state) {
    if (std::string(DRIFTLAB_AVR_ELF).empty() || !std::filesystem::exists(DRIFTLAB_AVR_ELF)) {
        state.SkipWithError("AVR firmware ELF not built (avr-g++ missing)");
        return false;
    }
    return true;
}

// Streams `config` for `duration_s` of emulated time with the paper's sensor model; reports emulated s per wall s.
void stream_recording(benchmark::State& state, proto::ConfigPayload config, double duration_s) {
    if (!have_elf(state)) {
        return;
    }
    for (auto _ : state) {
        auto model = std::make_shared<sim::SensorModel>(sim::parse_model(sim::paper_model_text(), "paper"), 1);
        AvrBoard board(AvrBoardOptions{DRIFTLAB_AVR_ELF}, [model](Channel c, std::uint64_t tick) {
            return millivolts_for_code(model->convert(c, static_cast<double>(tick) / fw::kTickHz).code);
        });
        board.run_until_armed();
        std::uint8_t frame[proto::kMaxFrameSize];
        board.receive(frame, proto::encode_config_set(config, {nullptr, 1}, 0, frame, sizeof frame));
        std::uint8_t out[4096];
        std::size_t bytes = 0;
        for (double t = 1.0; t <= duration_s; t += 1.0) {
            board.run_until_s(t);
            for (std::size_t n; (n = board.transmit(out, sizeof out)) > 0;) {
                bytes += n;
            }
        }
        benchmark::DoNotOptimize(bytes);
        state.counters["emulated_s"] = duration_s;
        state.counters["load_pct"] = 100.0 * (1.0 - static_cast<double>(board.sleep_cycles()) / board.cycle());
    }
    state.counters["emulated_s_per_wall_s"] =
        benchmark::Counter(duration_s * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_AvrFig3_4000s_1Hz(benchmark::State& state) { stream_recording(state, {1000, 25, 25, 0, 1, 0}, 4000.0); }
void BM_AvrFig2_1000x100ms(benchmark::State& state) { stream_recording(state, {100, 25, 25, 0, 1, 0}, 100.0); }

void print_budget(const CycleBudget& b) {
    std::printf(
        "config %u ms / %u conv: period %u ticks = %.0f conversions/s (all channels), load %.1f %%, "
        "dropped %u, tx_overflow %u, stack %u of %u bytes%s\n",
        b.config.output_period_ms, b.config.conversions_per_output, b.conversion_period_ticks, b.conversions_per_s,
        100.0 * b.cpu_load, b.dropped, b.tx_overflow, b.stack_high_water_bytes, b.stack_budget_bytes,
        b.accepted ? "" : " (CONFIG_SET refused)");
    for (const FunctionCycles& f : b.functions) {
        std::printf("  %-17s calls %8llu  mean %7.1f  max %6llu cycles\n", f.label.c_str(),
                    static_cast<unsigned long long>(f.calls), f.mean_cycles(),
                    static_cast<unsigned long long>(f.max_cycles));
    }
}

// Default configuration (1000 conversions/s), profiled: per-call cycles of the ISRs and the fit.
void BM_AvrCycleBudgetDefault(benchmark::State& state) {
    if (!have_elf(state)) {
        return;
    }
    for (auto _ : state) {
        const CycleBudget b = measure_cycle_budget(DRIFTLAB_AVR_ELF, {100, 25, 25, 0, 1, 1}, 0.5, 5.0, true);
        print_budget(b);
        state.counters["load_pct"] = 100.0 * b.cpu_load;
        state.counters["adc_isr_cycles"] = b.functions.empty() ? 0.0 : b.functions[0].mean_cycles();
        state.counters["stack_bytes"] = b.stack_high_water_bytes;
    }
}

// Fastest conversion rate streaming SAMPLE + RAW at 115200 baud without losing a conversion.
void BM_AvrMaxSustainedRate(benchmark::State& state) {
    if (!have_elf(state)) {
        return;
    }
    for (auto _ : state) {
        const std::vector<CycleBudget> results = search_max_rate(DRIFTLAB_AVR_ELF, 3.0);
        double best = 0.0;
        for (const CycleBudget& b : results) {
            print_budget(b);
            if (b.accepted && b.dropped == 0 && b.tx_overflow == 0 && b.conversions_per_s > best) {
                best = b.conversions_per_s;
            }
        }
        state.counters["max_conversions_per_s"] = best;
    }
}

}  // namespace

BENCHMARK(BM_AvrFig3_4000s_1Hz)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_AvrFig2_1000x100ms)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_AvrCycleBudgetDefault)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_AvrMaxSustainedRate)->Iterations(1)->Unit(benchmark::kSecond);
