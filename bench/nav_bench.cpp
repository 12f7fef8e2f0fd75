// Navigation speed on one core: `nav`'s four variants (the filter with zero-velocity updates at detected stops) over
// an hour of stop-and-go from power-on at 0.1 s rows, as rows per wall second and navigated seconds per wall second.
// The accuracy figures are nav-eval's (docs/nav.md); this prints time only.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "host/nav/navigate.hpp"
#include "sim/hil/hil.hpp"
#include "sim/hil/hil_preset.hpp"
#include "sim/model/drift.hpp"
#include "sim/model/model_file.hpp"
#include "sim/motion/trajectories.hpp"

namespace {

using namespace driftlab;

// An hour of stop-and-go at 0.1 s rows (4 conversions per channel each), as the host logs it.
const host::LogData& hour_log() {
    static const host::LogData log = [] {
        sim::HilOptions o;
        o.model = sim::paper_model();
        sim::apply_preset(sim::Preset::fig3, o);
        o.model.firmware.output_period_ms = 100;
        o.model.firmware.conversions_per_output = 4;
        o.model.firmware.window = 4;
        o.duration_s = 3600.0;
        o.trajectory =
            std::make_shared<const sim::Trajectory>(sim::make_trajectory("stop-and-go", o.duration_s + 60.0, 10.0, 1));
        host::LogData l;
        l.source_name = "bench";
        sim::run_hil(o, [&l](const sim::HilRecord& r) {
            l.t_s.push_back(r.t_s);
            l.seq.push_back(r.seq);
            for (std::size_t c = 0; c < kChannelCount; ++c) l.counts[c].push_back(r.value_counts[c]);
        });
        return l;
    }();
    return log;
}

// Table 1 and a white noise of 0.3 counts per 0.1 s row: the unit's model as --fit-from would give it.
host::nav::UnitDrift table1() {
    host::nav::UnitDrift u;
    for (std::size_t k = 0; k < host::nav::kNavAxes; ++k) {
        const sim::DriftParams& p = sim::kPaperDrift[channel_index(host::nav::kNavChannels[k])];
        u.axes[k].drift = {p.c1_counts, p.c2_counts, p.tau_s};
        u.axes[k].white_density = 0.3 * std::sqrt(0.1);
    }
    return u;
}

void BM_NavStopAndGoHour10Hz(benchmark::State& state) {
    const host::LogData& log = hour_log();
    host::nav::NavOptions o;
    o.aid.zupt = true;
    const auto unit = table1();
    for (auto _ : state) {
        const host::nav::NavRun run = host::nav::navigate(log, sim::paper_model(), unit, std::nullopt, o);
        benchmark::DoNotOptimize(run.tracks.back().x_m.back());
    }
    const double rows = static_cast<double>(log.size() * state.iterations());
    state.counters["rows_per_s"] = benchmark::Counter(rows, benchmark::Counter::kIsRate);
    state.counters["real_time_factor"] = benchmark::Counter(
        (log.t_s.back() - log.t_s.front()) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_NavStopAndGoHour10Hz)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
