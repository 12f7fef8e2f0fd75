// The board's smoothed outputs at given instants, without the link: per conversion the one sensor chain
// (sensor_model.hpp), then the firmware's own smoother (fw::LsWindow, bit-exact Q8 output) at each output instant.
// What the gap diagnosis simulates its replicates with (docs/gap.md §Model); `hil` adds the firmware's framing, the
// link and the host to the same chain.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "driftlab/channels.hpp"
#include "sim/model/sensor_model.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::sim {

/// The firmware's least-squares smoothing and output timing (log metadata; docs/log-format.md).
struct Smoothing {
    double sample_period_s = 1.0;    ///< the rows' period, the spacing every lag and band counts [s]
    int conversions_per_output = 1;  ///< conversions of each channel per output [-]
    int window = 1;                  ///< N of the sliding least-squares fit [conversions]
    int fit_order = 0;               ///< 0 = mean, 1 = line evaluated at the newest conversion
    /// Outputs the firmware made per row: 1 when every output is a row; more for polled rows that come slower than
    /// the outputs (a board paced faster than the recorder's clock, `hil --pty --speed 10` with `record --poll`).
    double outputs_per_row = 1.0;

    double output_period_s() const { return sample_period_s / outputs_per_row; }
    double conversion_period_s() const { return output_period_s() / conversions_per_output; }
};

/// What the outputs are simulated from.
struct OutputModel {
    SimModel unit;  ///< front ends and converter (its own drift, noise and effects unused)
    Smoothing smoothing;
    ChannelBases base{};              ///< eq. 1 and white noise per channel
    std::vector<EffectSpec> effects;  ///< the effects of the chain
};

/// Converter counts per physical unit of a channel [counts per deg/s or per g].
double counts_per_unit(const OutputModel& model, Channel c);

/// Eq. 1's drift less mid-scale [counts] at each conversion instant simulate_outputs() visits, in its order, per
/// channel (empty for channels not asked for): the same for every seed of one model.
using DriftAtConversions = std::array<std::vector<double>, kChannelCount>;

/// What the shared drift may hold: 32 MiB, the four channels of about 20 min at 100 Hz with 8 conversions per output
/// (every gap-eval log). Sharing saves about a tenth of a replicate's time on a short log; on an hour's log at 128 MiB
/// it was the largest block of gap's peak (92 MB) and saved no measurable time (119 s with it, 115 s without).
inline constexpr std::size_t kSharedDriftBytes = std::size_t{32} << 20;

/// The drift of `model` at its conversion instants for the output instants `t_s`, for its replicates to share; none
/// where a timing effect moves the instants (they then differ by seed), or where it would exceed `max_bytes`
/// (each replicate then evaluates eq. 1 itself, to the same values).
std::optional<DriftAtConversions> drift_at_conversions(const OutputModel& model, const std::vector<double>& t_s,
                                                       const std::array<bool, kChannelCount>& channels,
                                                       std::size_t max_bytes = kSharedDriftBytes);

/// What to simulate: the output instants and, for the withheld-effect benchmark, signals added at the converter
/// input (a truth generator's output, held over each output period).
struct OutputRequest {
    const std::vector<double>* t_s = nullptr;                          ///< output instants [s since power-on]
    std::array<bool, kChannelCount> channels{true, true, true, true};  ///< channels to simulate
    std::array<std::vector<double>, kChannelCount> added_counts;       ///< per output sample [counts]; empty = none
    std::array<Quantiser, kChannelCount> quantiser;                    ///< per channel; empty = the model's converter
    /// Optional: receives per requested channel the newest conversion's code at each output instant, the raw
    /// column of a raw-mode log [counts].
    std::array<std::vector<double>, kChannelCount>* raw_codes = nullptr;
    /// Optional: drift_at_conversions() of the model simulated and these t_s and channels, instead of eq. 1 per
    /// conversion (about a tenth of a replicate's time on a long log).
    const DriftAtConversions* drift = nullptr;
};

/// Smoothed outputs [counts] per channel (empty for channels not requested).
using Outputs = std::array<std::vector<double>, kChannelCount>;

/// Simulates the outputs with every random component seeded from `seed`. Each channel's conversions are those
/// that can change its outputs: the window holds the last N conversions, so older ones are not simulated (all are
/// when N is at least the conversions per output), and a channel's codes are those SensorModel gives at the same
/// instants (tests/sim/hil/chain_parity_test.cpp).
Outputs simulate_outputs(const OutputModel& model, const OutputRequest& request, std::uint64_t seed);

}  // namespace driftlab::sim
