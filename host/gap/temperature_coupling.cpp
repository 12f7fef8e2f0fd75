// The channels against the measured temperature; see temperature_coupling.hpp.
#include "host/gap/temperature_coupling.hpp"

#include <algorithm>
#include <cmath>

#include "host/gap/common_cause.hpp"

namespace driftlab::host::gap {
namespace {

// As a shared reading's: "positive" evidence on the Schwarz criterion (common_cause.cpp).
constexpr double kCouplingMargin = 2.0;

std::array<const std::vector<double>*, kChannelCount> pointers(
    const std::array<std::vector<double>, kChannelCount>& residuals, const std::array<bool, kChannelCount>& channels) {
    std::array<const std::vector<double>*, kChannelCount> out{};
    for (std::size_t c = 0; c < kChannelCount; ++c)
        if (channels[c]) out[c] = &residuals[c];
    return out;
}

}  // namespace

bool TemperatureCoupling::any() const {
    return std::any_of(coupled.begin(), coupled.end(), [](bool b) { return b; });
}

std::vector<double> temperature_residual(const LogData& log) {
    const auto column = log.optional_columns.find("temp_c");
    if (column == log.optional_columns.end() || column->second.size() != log.size()) return {};
    const std::vector<double>& t = column->second;
    if (std::any_of(t.begin(), t.end(), [](double v) { return !std::isfinite(v) || v <= kNoTemperatureC; })) return {};
    if (std::all_of(t.begin(), t.end(), [&](double v) { return v == t.front(); })) return {};
    return common_residual(log.t_s, t, {});
}

TemperatureCoupling couple_to_temperature(std::array<std::vector<double>, kChannelCount>& residuals,
                                          const std::array<bool, kChannelCount>& channels,
                                          const std::vector<double>& temperature, const GapModel& model, int threads) {
    TemperatureCoupling out;
    if (temperature.empty() || std::count(channels.begin(), channels.end(), true) < 2) return out;
    out.compared = true;
    double tt = 0.0;
    for (double v : temperature) tt += v * v;
    out.temperature_sd_c = std::sqrt(tt / static_cast<double>(temperature.size()));
    std::array<std::vector<double>, kChannelCount> regressed = residuals;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (!channels[c]) continue;
        double ty = 0.0;
        for (std::size_t k = 0; k < temperature.size(); ++k) ty += temperature[k] * residuals[c][k];
        out.coefficient[c] = ty / tt;
        for (std::size_t k = 0; k < temperature.size(); ++k) regressed[c][k] -= out.coefficient[c] * temperature[k];
    }
    const SeparateReading before = read_channels_alone(pointers(residuals, channels), model, threads);
    const SeparateReading after = read_channels_alone(pointers(regressed, channels), model, threads);
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (!channels[c]) continue;
        out.gain[c] = before.fit.channel_criterion[c] - after.fit.channel_criterion[c];
        out.coupled[c] = out.gain[c] > before.price + kCouplingMargin;
        if (out.coupled[c])
            residuals[c] = std::move(regressed[c]);
        else
            out.coefficient[c] = 0.0;
    }
    return out;
}

}  // namespace driftlab::host::gap
