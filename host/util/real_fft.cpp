// Real transforms by FFTW, with per-thread plans; see real_fft.hpp.
#include "host/util/real_fft.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include <fftw3.h>

namespace driftlab::host {
namespace {

// FFTW's planner is not thread-safe (its execution is): plans are made and destroyed under this lock.
std::mutex& planner_lock() {
    static std::mutex m;
    return m;
}

enum class Direction { forward, inverse };

// FFTW_ESTIMATE plans by rule, never by timing trial transforms, so a run repeats digit for digit. The vector
// codelets it picks follow the CPU (SSE2, AVX2, AVX-512): DRIFTLAB_FFT_PORTABLE=1 plans without them, for the
// same digits on every x86-64 node of a mixed cluster (about half the speed; docs/performance.md §FFT).
unsigned planner_flags() {
    static const unsigned flags = [] {
        const char* portable = std::getenv("DRIFTLAB_FFT_PORTABLE");
        return portable && std::string(portable) == "1" ? FFTW_ESTIMATE | FFTW_NO_SIMD : FFTW_ESTIMATE;
    }();
    return flags;
}

// A plan with its own aligned buffers: the caller's vectors are copied through them, so the plan's alignment
// assumptions always hold (a copy costs a few per cent of a transform).
struct Plan {
    std::size_t n = 0;
    Direction direction = Direction::forward;
    std::uint64_t last_use = 0;
    double* real = nullptr;
    fftw_complex* bins = nullptr;
    fftw_plan plan = nullptr;

    Plan(std::size_t length, Direction d) : n(length), direction(d) {
        const std::lock_guard<std::mutex> lock(planner_lock());
        real = fftw_alloc_real(n);
        bins = fftw_alloc_complex(n / 2 + 1);
        if (!real || !bins) throw std::bad_alloc();
        const int len = static_cast<int>(n);
        plan = d == Direction::forward ? fftw_plan_dft_r2c_1d(len, real, bins, planner_flags())
                                       : fftw_plan_dft_c2r_1d(len, bins, real, planner_flags());
        if (!plan) throw std::runtime_error("FFTW could not plan a transform of " + std::to_string(n) + " points");
    }
    Plan(const Plan&) = delete;
    Plan& operator=(const Plan&) = delete;
    ~Plan() {
        const std::lock_guard<std::mutex> lock(planner_lock());
        fftw_destroy_plan(plan);
        fftw_free(real);
        fftw_free(bins);
    }
};

// A fit transforms one or two lengths thousands of times; a few more are kept for the callers between its steps.
constexpr std::size_t kKeptPlans = 8;

// This thread's plan for n points in direction d, made on first use; the least recently used is dropped for it.
Plan& thread_plan(std::size_t n, Direction d) {
    thread_local std::vector<std::unique_ptr<Plan>> plans;
    thread_local std::uint64_t clock = 0;
    ++clock;
    for (auto& p : plans)
        if (p->n == n && p->direction == d) {
            p->last_use = clock;
            return *p;
        }
    if (plans.size() == kKeptPlans)
        plans.erase(std::min_element(plans.begin(), plans.end(),
                                     [](const auto& a, const auto& b) { return a->last_use < b->last_use; }));
    plans.push_back(std::make_unique<Plan>(n, d));
    plans.back()->last_use = clock;
    return *plans.back();
}

}  // namespace

std::vector<std::complex<double>> half_spectrum(const std::vector<double>& x) {
    if (x.size() < 2) return {x.begin(), x.end()};
    Plan& p = thread_plan(x.size(), Direction::forward);
    std::copy(x.begin(), x.end(), p.real);
    fftw_execute(p.plan);
    std::vector<std::complex<double>> out(x.size() / 2 + 1);
    // std::complex<double> is an array of two doubles, as fftw_complex is (C++20 [complex.numbers]/4, FFTW §4.1.1).
    std::copy_n(p.bins[0], 2 * out.size(), reinterpret_cast<double*>(out.data()));
    return out;
}

std::vector<double> real_series(const std::vector<std::complex<double>>& half, std::size_t n) {
    if (half.size() != n / 2 + 1 || n == 0)
        throw std::invalid_argument("real_series: " + std::to_string(half.size()) + " bins for " + std::to_string(n) +
                                    " points (want n/2 + 1)");
    if (n == 1) return {half[0].real()};
    Plan& p = thread_plan(n, Direction::inverse);
    std::copy_n(reinterpret_cast<const double*>(half.data()), 2 * half.size(), p.bins[0]);
    fftw_execute(p.plan);  // destroys p.bins, the plan's own copy
    std::vector<double> out(p.real, p.real + n);
    const double scale = 1.0 / static_cast<double>(n);
    for (double& v : out) v *= scale;
    return out;
}

}  // namespace driftlab::host
