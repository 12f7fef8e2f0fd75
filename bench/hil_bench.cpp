// Host-in-the-loop speed on one core: the fig3 preset end to end (sensor model, firmware core on NativeBoard,
// link, host decoder), as simulated seconds per wall second, the same with the unit riding the figure8 and
// stop-and-go trajectories at 0.1 s outputs, and the sensor model alone per conversion.
// Prints figures only; the target is >= 1000x real time.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "sim/hil/hil.hpp"
#include "sim/hil/hil_preset.hpp"
#include "sim/model/model_file.hpp"
#include "sim/model/sensor_model.hpp"
#include "sim/motion/trajectories.hpp"

namespace {

using driftlab::Channel;
using namespace driftlab::sim;

void run_options(benchmark::State& state, const HilOptions& o) {
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

HilOptions preset_options(Preset preset) {
    HilOptions o;
    o.model = paper_model();
    apply_preset(preset, o);
    return o;
}

// An hour on a trajectory at 0.1 s outputs (4 conversions per channel each).
HilOptions moving(const std::string& trajectory) {
    HilOptions o = preset_options(Preset::fig3);
    o.model.firmware.output_period_ms = 100;
    o.model.firmware.conversions_per_output = 4;
    o.model.firmware.window = 4;
    o.duration_s = 3600.0;
    o.trajectory = std::make_shared<const Trajectory>(make_trajectory(trajectory, o.duration_s + 60.0, 10.0, 1));
    return o;
}

void BM_HilFig3(benchmark::State& state) { run_options(state, preset_options(Preset::fig3)); }
BENCHMARK(BM_HilFig3)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_HilFig2(benchmark::State& state) { run_options(state, preset_options(Preset::fig2)); }
BENCHMARK(BM_HilFig2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_HilFigure8Hour(benchmark::State& state) { run_options(state, moving("figure8")); }
BENCHMARK(BM_HilFigure8Hour)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_HilStopAndGoHour(benchmark::State& state) { run_options(state, moving("stop-and-go")); }
BENCHMARK(BM_HilStopAndGoHour)->Unit(benchmark::kMillisecond)->UseRealTime();

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
