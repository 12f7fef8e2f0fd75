// One simulated log of the calibrated model, made the way the board makes it: per conversion the sensor chain
// (physical effects, front end, analog effects, eq. 1 drift, white noise, converter effects, 10-bit quantiser),
// then the firmware's own smoother (fw::LsWindow, bit-exact Q8 output) evaluated at each output instant.
// The frame/link layer is left out: the log's sequence numbers are compared separately (statistics.hpp).
// docs/gap.md §Model.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "host/gap/gap_model.hpp"

namespace driftlab::host::gap {

/// A converter that replaces the model's converter effects and 10-bit quantiser (gap-eval's converter truth): the
/// code of a converter input [counts].
using Quantiser = std::function<int(double input_counts)>;

/// Eq. 1's drift less mid-scale [counts] at each conversion instant simulate() visits, in its order, per channel
/// (empty for channels not asked for): the same for every replicate of one model.
using DriftAtConversions = std::array<std::vector<double>, kChannelCount>;

/// What the shared drift may hold: 128 MiB, the four channels of about 1.4 h at 100 Hz with 8 conversions per output.
/// Sharing saves about a tenth of a replicate's time; on a longer log that is not worth a block growing with it.
inline constexpr std::size_t kSharedDriftBytes = std::size_t{128} << 20;

/// The drift of `model` at its conversion instants for the output instants `t_s`, for its replicates to share; none
/// where a timing effect moves the instants (they then differ by seed), or where it would exceed `max_bytes`
/// (each replicate then evaluates eq. 1 itself, to the same values).
std::optional<DriftAtConversions> drift_at_conversions(const GapModel& model, const std::vector<double>& t_s,
                                                       const std::array<bool, kChannelCount>& channels,
                                                       std::size_t max_bytes = kSharedDriftBytes);

/// What to simulate: the output instants and, for the withheld-effect benchmark, signals added at the converter
/// input (a truth generator's output, held over each output period).
struct SimRequest {
    const std::vector<double>* t_s = nullptr;                    ///< output instants [s since power-on]
    std::array<bool, kChannelCount> channels{true, true, true, true};  ///< channels to simulate
    std::array<std::vector<double>, kChannelCount> added_counts;  ///< per output sample [counts]; empty = none
    std::array<Quantiser, kChannelCount> quantiser;  ///< per channel; empty = the model's converter
    /// Optional: receives per requested channel the newest conversion's code at each output instant, the raw
    /// column of a raw-mode log [counts].
    std::array<std::vector<double>, kChannelCount>* raw_codes = nullptr;
    /// Optional: drift_at_conversions() of the model simulated and these t_s and channels, instead of eq. 1 per
    /// conversion (about a tenth of a replicate's time on a long log).
    const DriftAtConversions* drift = nullptr;
};

/// Smoothed outputs [counts] per channel (empty for channels not requested).
using SimOutput = std::array<std::vector<double>, kChannelCount>;

/// Simulates one replicate with every random component seeded from `seed`.
SimOutput simulate(const GapModel& model, const SimRequest& request, std::uint64_t seed);

}  // namespace driftlab::host::gap
