// Host-in-the-loop speed on one core: the fig3 preset end to end (sensor model, firmware core on NativeBoard,
// link, host decoder), as simulated seconds per wall second, and the sensor model alone per conversion.
// Prints figures only; the target is >= 1000x real time.
#include <benchmark/benchmark.h>

#include "sim/hil/hil.hpp"
#include "sim/hil/hil_preset.hpp"
#include "sim/model/model_file.hpp"
#include "sim/model/sensor_model.hpp"

namespace {

using driftlab::Channel;
using namespace driftlab::sim;

void run_preset(benchmark::State& state, Preset preset) {
    HilOptions o;
    o.model = paper_model();
    apply_preset(preset, o);
    double simulated_s = 0.0;
    double conversions = 0.0;
    std::uint64_t rows = 0;
    for (auto _ : state) {
        const HilSummary s = run_hil(o, [&rows](const HilRecord&) { ++rows; });
        simulated_s += s.simulated_s;
        conversions += static_cast<double>(s.conversions);
    }
    benchmark::DoNotOptimize(rows);
    // Rates divide by the measured wall time: simulated seconds per wall second = the real-time factor.
    state.counters["real_time_factor"] = benchmark::Counter(simulated_s, benchmark::Counter::kIsRate);
    state.counters["s_per_conversion"] =
        benchmark::Counter(conversions, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_HilFig3(benchmark::State& state) { run_preset(state, Preset::fig3); }
BENCHMARK(BM_HilFig3)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_HilFig2(benchmark::State& state) { run_preset(state, Preset::fig2); }
BENCHMARK(BM_HilFig2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SensorModelConversion(benchmark::State& state) {
    SensorModel sensor(paper_model(), 1);
    double t_s = 0.0;
    int c = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(sensor.convert(static_cast<Channel>(c), t_s));
        c = (c + 1) & 3;
        t_s += 0.0025;
    }
}
BENCHMARK(BM_SensorModelConversion);

}  // namespace
