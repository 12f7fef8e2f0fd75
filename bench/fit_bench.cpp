// Time to fit eq. 1 (automatic start + Levenberg–Marquardt + covariance) on one core, and the whole per-channel
// analysis (fit, whiteness, intervals). Reference: scipy.optimize.curve_fit takes about 1 ms for 4000 samples
// and 0.28 s for 10^6 on the same kind of data; the aim is 5x faster.
#include <benchmark/benchmark.h>

#include <cmath>

#include "host/fit/drift_analysis.hpp"
#include "host/fit/lm_fit.hpp"
#include "sim/model/rng.hpp"

namespace {

using driftlab::host::fit::Series;

/// Paper gyro row (C1 = 3, C2 = 505, T = 411 s) sampled so that n samples span 4000 s, plus white noise.
Series paper_gyro(std::size_t n) {
    driftlab::sim::Rng rng(42, 1);
    Series s;
    s.name = "gyro";
    s.source = "bench";
    const double period_s = 4000.0 / static_cast<double>(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double t = period_s * static_cast<double>(k + 1);
        s.t_s.push_back(t);
        s.values.push_back(3.0 * (1.0 - std::exp(-t / 411.0)) + 505.0 + 0.256 * rng.normal());
    }
    return s;
}

void BM_FitDrift(benchmark::State& state) {
    const Series s = paper_gyro(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) {
        auto fit = driftlab::host::fit::fit_drift(s.t_s, s.values);
        benchmark::DoNotOptimize(fit.parameters);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_FitDrift)->Arg(4000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_AnalyseDrift(benchmark::State& state) {
    const Series s = paper_gyro(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) {
        auto a = driftlab::host::fit::analyse_drift(s);
        benchmark::DoNotOptimize(a.plain.c1.value);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_AnalyseDrift)->Arg(4000)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace
