// The channels against the temperature the log measured (its temp_c column): each channel's residual regressed on
// the temperature's, both less an eq. 1 fit (the warm-up they share is eq. 1's, not a coupling), and judged channel by
// channel by the Whittle criterion of the channel read alone (common_cause.hpp) with and without the regression. A
// coupling fitted against the measured temperature replaces a free process standing for it; what is left is read
// again, alone and together. docs/gap.md §Shared causes.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "host/gap/gap_model.hpp"
#include "host/log/log_data.hpp"

namespace driftlab::host::gap {

struct TemperatureCoupling {
    bool compared = false;          ///< the log has a varying temperature in every row, and two channels or more
    double temperature_sd_c = 0.0;  ///< the temperature's residual (eq. 1 out), standard deviation
    std::array<double, kChannelCount> coefficient{};  ///< counts per degC (0 where not coupled)
    std::array<double, kChannelCount> gain{};         ///< the channel's criterion without the regression minus with it
    std::array<bool, kChannelCount> coupled{};        ///< gain above one parameter's price plus the margin
    bool any() const;
};

/// The log's temperature residual (temp_c less an eq. 1 fit), or empty where the log has none in some row or it
/// never changes.
std::vector<double> temperature_residual(const LogData& log);

/// Regresses `residuals` (per channel; null for channels not analysed) on `temperature` (temperature_residual()) and
/// takes the coupling out of the channels where it pays (the channels' fits on `threads` threads).
TemperatureCoupling couple_to_temperature(std::array<std::vector<double>, kChannelCount>& residuals,
                                          const std::array<bool, kChannelCount>& channels,
                                          const std::vector<double>& temperature, const GapModel& model, int threads);

}  // namespace driftlab::host::gap
