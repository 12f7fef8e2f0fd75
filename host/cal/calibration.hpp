// Calibration: what `calibrate` makes of a log's eq. 1 fit and what `upload` and `hil --cal` send to a board: per
// channel C1, C2 and T with their 95 % intervals, whether the channel is referred to mid-scale, and an id. Its file
// is CAL.json (cal_file.hpp); its wire form the four CAL_SET payloads, converted here and nowhere else.
// docs/calibration.md.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "driftlab/channels.hpp"
#include "driftlab/proto/messages.hpp"
#include "host/fit/drift_model.hpp"
#include "host/fit/file_analysis.hpp"

namespace driftlab::host::cal {

struct ChannelCalibration {
    fit::DriftParameters model;  ///< C1, C2 [counts], T [s]
    /// 95 % intervals of C1, C2 [counts] and T [s] from the fit (widened for a coloured residual); NaN when unknown.
    std::array<double, 2> c1_ci95{}, c2_ci95{}, t_ci95{};
    bool zero = false;  ///< the board refers the settled level to mid-scale (512 counts) too
};

struct Calibration {
    std::uint16_t id = 0;  ///< 1..65535, what SAMPLE.cal_id reports
    std::string source;    ///< the log it was fitted to
    std::array<ChannelCalibration, kChannelCount> channels{};
};

/// Which channels are referred to zero unless told otherwise: the rate gyro (its zero-rate code is mid-scale); not
/// the accelerometers, whose settled level holds gravity in the pose they were calibrated in.
inline constexpr std::array<bool, kChannelCount> kDefaultZero = {true, false, false, false};

/// From the fit of every channel of a log. Throws DataError naming the log when a channel was not fitted or its C1
/// and T are not determined, when the log's outputs were compensated on board already (fitting them again would
/// compensate twice), or a value lies outside what a board accepts. `id` unset: content_id().
Calibration from_fit(const fit::FileAnalysis& file, const std::array<bool, kChannelCount>& zero,
                     std::optional<std::uint16_t> id);

/// The four CAL_SET payloads, channel order: C1 and C2 in Q8 counts and T in ms, each rounded to nearest. Throws
/// DataError naming `where` and the channel when a value is outside the board's ranges (docs/protocol.md §3.12).
std::array<proto::CalPayload, kChannelCount> to_payloads(const Calibration& cal, const std::string& where);

/// An id for a calibration that has none: CRC-16 of its payloads (with cal_id 0), 1 where that is 0; the same model
/// gets the same id.
std::uint16_t content_id(const Calibration& cal);

}  // namespace driftlab::host::cal
