// Cost of the Allan statistics on one core. Reference point (docs/allan.md §9): a vectorised numpy OADEV
// (allantools style) takes about 0.15 s for an octave grid on 10^6 samples on this class of machine.
// Prints figures only.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "host/stats/allan_analysis.hpp"
#include "host/stats/deviation.hpp"
#include "host/stats/phase_record.hpp"
#include "host/stats/tau_grid.hpp"

namespace {

using namespace driftlab::host::stats;

const std::vector<double>& rate_samples(std::size_t n) {
    static std::vector<double> cache;
    if (cache.size() != n) {
        std::mt19937_64 rng(7);
        std::normal_distribution<double> g(512.0, 0.7);  // a 10-bit ADC at mid-scale
        cache.resize(n);
        for (double& v : cache) v = g(rng);
    }
    return cache;
}

// Rate samples in, octave OADEV out: phase integration plus every octave tau.
void BM_OadevOctaveFromRate(benchmark::State& state) {
    const auto& y = rate_samples(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) {
        const PhaseRecord r = PhaseRecord::from_rate(y, 0.01);
        const auto ms = analysis_factors(r, Deviation::oadev, {TauGrid::octave});
        benchmark::DoNotOptimize(compute_deviation(r, Deviation::oadev, ms));
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_OadevOctaveFromRate)->Arg(1000000)->Arg(10000000)->Unit(benchmark::kMillisecond);

template <Deviation kDev>
void BM_DeviationOctaveOnRecord(benchmark::State& state) {
    const PhaseRecord r = PhaseRecord::from_rate(rate_samples(static_cast<std::size_t>(state.range(0))), 0.01);
    const auto ms = analysis_factors(r, kDev, {TauGrid::octave});
    for (auto _ : state) benchmark::DoNotOptimize(compute_deviation(r, kDev, ms));
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_DeviationOctaveOnRecord<Deviation::oadev>)->Arg(1000000)->Arg(10000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DeviationOctaveOnRecord<Deviation::mdev>)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DeviationOctaveOnRecord<Deviation::ohdev>)->Arg(1000000)->Unit(benchmark::kMillisecond);

// Everything `driftlab allan` adds per curve: noise identification, EDF and intervals.
void BM_OadevOctaveWithIntervals(benchmark::State& state) {
    const PhaseRecord r = PhaseRecord::from_rate(rate_samples(static_cast<std::size_t>(state.range(0))), 0.01);
    const auto ms = analysis_factors(r, Deviation::oadev, {TauGrid::octave});
    for (auto _ : state) benchmark::DoNotOptimize(analyse_deviation(r, Deviation::oadev, ms));
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_OadevOctaveWithIntervals)->Arg(1000000)->Unit(benchmark::kMillisecond);

// All-tau on a short record: the O(N^2) case.
void BM_OadevAllTau(benchmark::State& state) {
    const PhaseRecord r = PhaseRecord::from_rate(rate_samples(static_cast<std::size_t>(state.range(0))), 0.01);
    const auto ms = analysis_factors(r, Deviation::oadev, {TauGrid::all});
    for (auto _ : state) benchmark::DoNotOptimize(compute_deviation(r, Deviation::oadev, ms));
}
BENCHMARK(BM_OadevAllTau)->Arg(40000)->Unit(benchmark::kMillisecond);

}  // namespace
