// The link truth generator: interference episodes that take frames away. truth.hpp.
#include <cmath>

#include "host/gap_eval/truth.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::host::gap {

std::vector<std::uint8_t> truth_interference_bursts(std::size_t frames, double loss_percent, std::uint64_t seed,
                                                    std::uint64_t noise_seed) {
    // The device: episodes whose lengths are log-normal (median 2-6 frames, ln-sd 0.7) and within which each frame is
    // lost with probability 0.7-1, arriving as a Poisson process at the rate that loses loss_percent of the frames
    // in the long run. Neither the lengths (not geometric) nor the losses within (not certain) are a Gilbert chain's.
    sim::Rng device(seed, 0x78);
    const double median = 2.0 + 4.0 * device.uniform();
    const double within = 0.7 + 0.3 * device.uniform();
    constexpr double kLnSd = 0.7;
    const double mean_length = median * std::exp(0.5 * kLnSd * kLnSd) + 0.5;  // rounded up to whole frames
    const double rate = loss_percent / 100.0 / (mean_length * within);
    sim::Rng rng(noise_seed, 0x79);
    std::vector<std::uint8_t> lost(frames, 0);
    for (std::size_t k = 0; k < frames; ++k) {
        if (rng.uniform() >= rate) continue;
        const auto length = static_cast<std::size_t>(std::ceil(median * std::exp(kLnSd * rng.normal())));
        for (std::size_t j = k; j < frames && j < k + length; ++j)
            if (rng.uniform() < within) lost[j] = 1;
        k += length;
    }
    return lost;
}

}  // namespace driftlab::host::gap
