// Wall time of `driftlab gap` (diagnose()) on a 4000 s log at 1 Hz and on a 1 h log at 100 Hz (8 conversions per
// output, window 8: sim/models/hundred_hz.toml), all four channels of the paper's unit, clean and with a second
// thermal time constant planted on the gyro so the candidate fits run too. Prints; never asserts.
#include <cmath>

#include <benchmark/benchmark.h>

#include "host/gap/diagnose.hpp"

#include "sim/model/board_outputs.hpp"

namespace {

using namespace driftlab;
using namespace driftlab::host;

struct LogShape {
    double period_s;
    std::size_t samples;
    int window;  ///< conversions per output = window, order 0
};
constexpr LogShape kFig3{1.0, 4000, 25};
constexpr LogShape kHundredHz{0.01, 360000, 8};

LogData paper_log(const LogShape& shape, bool planted) {
    gap::GapModel m;
    m.unit = sim::paper_model();
    m.unit.effects.clear();
    m.smoothing = {shape.period_s, shape.window, shape.window, 0};
    for (std::size_t c = 0; c < kChannelCount; ++c) m.base[c] = {sim::kPaperDrift[c], c == 0 ? 1.05 : 1.5};
    LogData log;
    log.source_name = "bench";
    for (std::size_t k = 0; k < shape.samples; ++k) {
        log.t_s.push_back(static_cast<double>(k + 1) * shape.period_s);
        log.seq.push_back(k);
    }
    sim::OutputRequest req;
    req.t_s = &log.t_s;
    if (planted) {
        req.added_counts[0].resize(log.t_s.size());
        for (std::size_t k = 0; k < log.t_s.size(); ++k)
            req.added_counts[0][k] = 2.0 * -std::expm1(-log.t_s[k] / 2000.0);
    }
    log.counts = sim::simulate_outputs(m, req, 42);
    log.metadata.set("sample_period_s", shape.period_s);
    log.metadata.set("conversions_per_output", static_cast<std::int64_t>(shape.window));
    log.metadata.set("window", static_cast<std::int64_t>(shape.window));
    log.metadata.set("fit_order", static_cast<std::int64_t>(0));
    return log;
}

void run(benchmark::State& state, const LogShape& shape, bool planted) {
    const LogData log = paper_log(shape, planted);
    gap::GapOptions o;
    for (auto _ : state) {
        const gap::GapResult r = gap::diagnose(log, sim::paper_model(), o);
        benchmark::DoNotOptimize(r.verdict);
        state.counters["located"] = static_cast<double>(r.located.size());
        state.counters["candidates"] = static_cast<double>(r.tried.size());
    }
}

void BM_GapCleanLog4000s(benchmark::State& state) { run(state, kFig3, false); }
void BM_GapPlantedLog4000s(benchmark::State& state) { run(state, kFig3, true); }
void BM_GapCleanLog1h100Hz(benchmark::State& state) { run(state, kHundredHz, false); }
void BM_GapPlantedLog1h100Hz(benchmark::State& state) { run(state, kHundredHz, true); }

BENCHMARK(BM_GapCleanLog4000s)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_GapPlantedLog4000s)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_GapCleanLog1h100Hz)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_GapPlantedLog1h100Hz)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
