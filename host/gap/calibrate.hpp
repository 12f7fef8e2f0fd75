// Calibration of the base simulator to a real log: the firmware's smoothing from the log's metadata, eq. 1 per
// channel by the same Levenberg-Marquardt fit the replicates get, and the white-noise level before the quantiser
// by a simulated-moment match of the short-lag spread (common random numbers, regula falsi). docs/gap.md §Model.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "host/gap/gap_model.hpp"
#include "host/log/log_data.hpp"

namespace driftlab::host::gap {

/// The smoothing recorded in the log (sample_period_s, conversions_per_output, window, fit_order); missing keys
/// take the median sample spacing, 1, 1 and 0. Throws DataError naming the key on an out-of-range value.
Smoothing smoothing_from_log(const LogData& log);

/// Channels worth analysing: those whose values are not all equal.
std::array<bool, kChannelCount> varying_channels(const LogData& log);

/// Short-lag spread of a residual [counts]: the standard deviation of first differences over sqrt 2, after
/// dropping differences beyond 6 robust deviations (spikes are a gap to find, not noise to calibrate on).
double short_lag_spread(const std::vector<double>& residual);

/// Sets `model.base[c].sigma_n_counts` for every selected channel so that the simulated short-lag spread of
/// the smoothed output matches `target_spread[c]`, with the model's drift and effects in place.
void match_noise(GapModel& model, const std::vector<double>& t_s, const std::array<bool, kChannelCount>& channels,
                 const std::array<double, kChannelCount>& target_spread, std::uint64_t seed);

/// The selected channels that `model` simulates alike for every seed: white noise below half a code (none, where the
/// log's spread needs none beyond the converter's, or too little to carry a conversion across a code boundary) and
/// no random effect. Their replicates cannot spread, so they give no null to compare with.
std::array<bool, kChannelCount> deterministic_channels(const GapModel& model, const std::vector<double>& t_s,
                                                       const std::array<bool, kChannelCount>& channels,
                                                       std::uint64_t seed);

/// The calibrated base model of `log` on `unit` (front ends and converter; not its effects), for the selected
/// channels. `spread` (optional) receives each channel's short-lag spread of the eq. 1 residual, the white noise's
/// target.
GapModel calibrate_base(const LogData& log, const sim::SimModel& unit, const std::array<bool, kChannelCount>& channels,
                        std::uint64_t seed, std::array<double, kChannelCount>* spread = nullptr);

}  // namespace driftlab::host::gap
