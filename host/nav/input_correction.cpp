#include "host/nav/input_correction.hpp"

#include <cmath>
#include <numbers>

#include "host/util/error.hpp"
#include "sim/model/board_outputs.hpp"
#include "sim/motion/trajectory.hpp"

namespace driftlab::host::nav {

std::array<double, kNavAxes> counts_per_si(const sim::SimModel& unit) {
    sim::OutputModel m;
    m.unit = unit;
    const double per_dps = sim::counts_per_unit(m, Channel::gyro);
    return {per_dps * 180.0 / std::numbers::pi, sim::counts_per_unit(m, Channel::accel_x) / sim::kStandardGravity,
            sim::counts_per_unit(m, Channel::accel_y) / sim::kStandardGravity};
}

InitialRest initial_rest(const LogData& log, double rest_s) {
    InitialRest r;
    if (log.size() == 0) throw DataError(log.source_name, 0, "the log has no rows");
    r.from_s = log.t_s.front();
    std::array<double, kNavAxes> sum{}, sum2{};
    for (std::size_t i = 0; i < log.size() && log.t_s[i] < r.from_s + rest_s; ++i, ++r.rows) {
        r.to_s = log.t_s[i];
        for (std::size_t k = 0; k < kNavAxes; ++k) {
            const double v = log.channel(kNavChannels[k])[i];
            sum[k] += v;
            sum2[k] += v * v;
        }
    }
    if (r.rows < 3)
        throw DataError(log.source_name, 0,
                        "fewer than 3 rows in the first " + std::to_string(rest_s) +
                            " s, where the unit must stand to take its bias (--rest)");
    const double n = static_cast<double>(r.rows);
    for (std::size_t k = 0; k < kNavAxes; ++k) {
        r.mean[k] = sum[k] / n;
        r.sd[k] = std::sqrt(std::max(0.0, (sum2[k] - n * r.mean[k] * r.mean[k]) / (n - 1.0)));
    }
    return r;
}

InputCorrection InputCorrection::constant(const InitialRest& rest) {
    InputCorrection c;
    c.constant_ = rest.mean;
    for (std::size_t k = 0; k < kNavAxes; ++k) c.sd_[k] = rest.sd[k] / std::sqrt(static_cast<double>(rest.rows));
    return c;
}

InputCorrection InputCorrection::eq1(const UnitDrift& unit) {
    InputCorrection c;
    c.drift_ = unit;
    for (std::size_t k = 0; k < kNavAxes; ++k) c.sd_[k] = unit.axes[k].drift_sd_counts;
    return c;
}

double InputCorrection::counts(std::size_t k, double t_s) const {
    return drift_ ? fit::drift_model(drift_->axes[k].drift, t_s) : constant_[k];
}

ImuReading reading(const LogData& log, std::size_t i, const InputCorrection& correction,
                   const std::array<double, kNavAxes>& counts_per_si) {
    std::array<double, kNavAxes> v{};
    for (std::size_t k = 0; k < kNavAxes; ++k)
        if (log.recorded[channel_index(kNavChannels[k])])
            v[k] = (log.channel(kNavChannels[k])[i] - correction.counts(k, log.t_s[i])) / counts_per_si[k];
    return {v[0], v[1], v[2]};
}

}  // namespace driftlab::host::nav
