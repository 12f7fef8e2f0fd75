// LsWindow on the host: time per conversion update (push) and per output evaluation (estimate_q8), for small and
// the largest windows and both orders. Prints figures only; the AVR cycle budget is in docs/firmware.md.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>
#include <vector>

#include "firmware/core/ls_window.hpp"

namespace {

using driftlab::fw::FitOrder;
using driftlab::fw::LsWindow;

std::vector<uint16_t> random_codes(size_t n) {
    std::mt19937 rng(1);
    std::uniform_int_distribution<int> code(0, 1023);
    std::vector<uint16_t> out(n);
    for (uint16_t& c : out) {
        c = static_cast<uint16_t>(code(rng));
    }
    return out;
}

void BM_LsWindowPush(benchmark::State& state) {
    const std::vector<uint16_t> codes = random_codes(4096);
    LsWindow lsw;
    lsw.reset(static_cast<uint8_t>(state.range(0)));
    size_t i = 0;
    for (auto _ : state) {
        lsw.push(codes[i++ & 4095U]);
        benchmark::DoNotOptimize(lsw);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LsWindowPush)->Arg(1)->Arg(16)->Arg(25)->Arg(64);

void BM_LsWindowEstimate(benchmark::State& state) {
    const std::vector<uint16_t> codes = random_codes(64);
    LsWindow lsw;
    lsw.reset(static_cast<uint8_t>(state.range(0)));
    for (uint16_t c : codes) {
        lsw.push(c);
    }
    const FitOrder order = state.range(1) == 0 ? FitOrder::mean : FitOrder::line;
    for (auto _ : state) {
        benchmark::DoNotOptimize(lsw);
        benchmark::DoNotOptimize(lsw.estimate_q8(order));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LsWindowEstimate)->Args({16, 0})->Args({16, 1})->Args({64, 0})->Args({64, 1});

}  // namespace
