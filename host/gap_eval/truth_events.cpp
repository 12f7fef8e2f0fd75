// The event truth generators: bursts of spikes and an out-of-library mode hop. truth.hpp.
#include <cmath>

#include "host/gap_eval/truth.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::host::gap {

std::vector<double> truth_burst_spikes(const std::vector<double>& t_s, double size_counts, std::uint64_t noise_seed) {
    // About one burst per 150 samples; each covers 1-3 whole output periods with one Laplace amplitude.
    sim::Rng rng(noise_seed, 0x76);
    std::vector<double> out(t_s.size(), 0.0);
    for (std::size_t k = 0; k < t_s.size(); ++k) {
        if (rng.uniform() >= 1.0 / 150.0) continue;
        const double u = rng.uniform() - 0.5;
        const double amp = -size_counts * (u < 0 ? -1.0 : 1.0) * std::log(1.0 - 2.0 * std::abs(u)) / std::sqrt(2.0);
        const std::size_t len = 1 + static_cast<std::size_t>(rng.uniform() * 3.0);
        for (std::size_t j = k; j < t_s.size() && j < k + len; ++j) out[j] += amp;
    }
    return out;
}

std::vector<double> truth_mode_hop(const std::vector<double>& t_s, double size_counts, std::uint64_t seed) {
    // A step of size_counts at 30-60 % of the log, and a return of 40-100 % of it at 65-90 %.
    sim::Rng rng(seed, 0x77);
    const double t0 = t_s.front(), span = t_s.back() - t_s.front();
    const double up = t0 + span * (0.3 + 0.3 * rng.uniform());
    const double down = t0 + span * (0.65 + 0.25 * rng.uniform());
    const double back = 0.4 + 0.6 * rng.uniform();
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    std::vector<double> out(t_s.size(), 0.0);
    for (std::size_t k = 0; k < t_s.size(); ++k) {
        if (t_s[k] >= up) out[k] += sign * size_counts;
        if (t_s[k] >= down) out[k] -= sign * size_counts * back;
    }
    return out;
}

}  // namespace driftlab::host::gap
