// The diagnosis's final model as a model file; see model_out.hpp.
#include "host/gap/model_out.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "firmware/core/config.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "sim/model/white_noise.hpp"

namespace driftlab::host::gap {

proto::ConfigPayload firmware_config(const Smoothing& s, bool raw, const std::string& source) {
    const double period_ms = std::round(s.output_period_s() * 1000.0);
    proto::ConfigPayload fw{static_cast<std::uint16_t>(std::clamp(period_ms, 0.0, 65535.0)),
                            static_cast<std::uint8_t>(std::clamp(s.conversions_per_output, 0, 255)),
                            static_cast<std::uint8_t>(std::clamp(s.window, 0, 255)),
                            static_cast<std::uint8_t>(s.fit_order),
                            static_cast<std::uint8_t>(proto::OutputMode::poll),
                            static_cast<std::uint8_t>(raw ? 1 : 0)};
    const bool exact = std::abs(period_ms - s.output_period_s() * 1000.0) <= 1e-6 * period_ms &&
                       period_ms == fw.output_period_ms && s.conversions_per_output == fw.conversions_per_output &&
                       s.window == fw.window;
    if (!exact || fw::validate(fw).status != proto::Status::ok) {
        char what[260];
        std::snprintf(what, sizeof what,
                      "--model-out: the log's smoothing (output period %.6g ms, %d conversions per output, window %d, "
                      "order %d) is "
                      "no CONFIG the firmware accepts (docs/protocol.md: a whole number of ms in 10..60000, 1..64, "
                      "1..64, 0 or 1)",
                      s.output_period_s() * 1000.0, s.conversions_per_output, s.window, s.fit_order);
        throw DataError(source, 0, what);
    }
    return fw;
}

ModelOut model_out(const GapModel& model, const std::array<bool, kChannelCount>& channels, bool raw,
                   const std::string& source) {
    ModelOut out{model.unit, {}};
    sim::SimModel& m = out.model;
    m.effects = model.effects;
    for (std::size_t i = 0; i < kChannelCount; ++i) {
        if (!channels[i]) continue;
        const Channel c = static_cast<Channel>(i);
        m.channels[i].drift = model.base[i].drift;
        // The file holds the raw codes' spread; below kMinCalibratedRawStdCounts no analog sigma reproduces a spread
        // reliably, so the file refuses it.
        const double sigma = model.base[i].sigma_n_counts;
        double raw_counts = sim::raw_std_counts_for_analog_sigma(sigma);
        if (raw_counts > 0.0 && raw_counts < sim::kMinCalibratedRawStdCounts) {
            out.notes.push_back(
                std::string(kChannelNames[i]) + ": white noise " + significant_plain(sigma, 3) +
                " counts before the quantiser written as " +
                significant_plain(sim::analog_sigma_for_raw_std_counts(sim::kMinCalibratedRawStdCounts), 3) +
                " (raw spread " + significant_plain(sim::kMinCalibratedRawStdCounts, 2) +
                " counts, the least a model file takes)");
            raw_counts = sim::kMinCalibratedRawStdCounts;
        }
        // The loader multiplies back by counts_per_unit; a quotient rounded down would read as just below the floor.
        const double cpu = counts_per_unit(model, c);
        double unit_std = raw_counts / cpu;
        while (unit_std * cpu < raw_counts) unit_std = std::nextafter(unit_std, INFINITY);
        m.channels[i].raw_noise_std_unit = unit_std;
    }
    const std::uint8_t mode = m.firmware.mode;
    m.firmware = firmware_config(model.smoothing, raw, source);
    m.firmware.mode = mode;
    m.name = model.unit.name + "+gap";
    return out;
}

}  // namespace driftlab::host::gap
