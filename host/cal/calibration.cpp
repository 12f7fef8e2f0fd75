// Calibration from a fit, and its fixed-point wire form (calibration.hpp).
#include "host/cal/calibration.hpp"

#include <cmath>
#include <string>

#include "driftlab/proto/crc16.hpp"
#include "host/log/compensation.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"

namespace driftlab::host::cal {
namespace {

std::int32_t to_q8(double counts) { return static_cast<std::int32_t>(std::lround(counts * 256.0)); }

void check_range(bool ok, const std::string& where, std::size_t c, const std::string& what) {
    if (!ok) throw DataError(where, 0, std::string(kChannelNames[c]) + ": " + what);
}

const ChannelCalibration& fitted_channel(const fit::FileAnalysis& file, std::size_t c, ChannelCalibration& out) {
    const fit::SeriesOutcome* found = nullptr;
    for (const auto& s : file.series)
        if (s.name == kChannelNames[c]) found = &s;
    if (found == nullptr || !found->analysis)
        throw DataError(file.path, 0,
                        std::string(kChannelNames[c]) + " was not fitted" + (found ? ": " + found->error : ""));
    const fit::DriftAnalysis& a = *found->analysis;
    if (!a.c1_and_t_determined())
        throw DataError(file.path, 0,
                        std::string(kChannelNames[c]) + ": " + a.undetermined_reason() +
                            "; record from power-on until the drift has settled to calibrate");
    out.model = a.fit.parameters;
    out.c1_ci95 = a.widened.c1.ci95;
    out.c2_ci95 = a.widened.c2.ci95;
    out.t_ci95 = a.widened.t_s.ci95;
    return out;
}

}  // namespace

Calibration from_fit(const fit::FileAnalysis& file, const std::array<bool, kChannelCount>& zero,
                     std::optional<std::uint16_t> id) {
    if (!file.log) throw DataError(file.path, 0, "not a driftlab log: a calibration is fitted to a board's log");
    if (const std::optional<std::string> why = compensated_on_board(file.log->metadata))
        throw DataError(file.path, 0,
                        *why +
                            ": fitting it again would compensate twice; record with the calibration "
                            "cleared (driftlab upload --clear) to calibrate afresh");
    Calibration cal;
    cal.source = file.path;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        fitted_channel(file, c, cal.channels[c]);
        cal.channels[c].zero = zero[c];
    }
    static_cast<void>(to_payloads(cal, file.path));  // refuses what no board would take, before anything is written
    cal.id = id ? *id : content_id(cal);
    return cal;
}

std::array<proto::CalPayload, kChannelCount> to_payloads(const Calibration& cal, const std::string& where) {
    std::array<proto::CalPayload, kChannelCount> out{};
    const double max_counts = proto::kCalCountsMaxQ8 / 256.0;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        const fit::DriftParameters& m = cal.channels[c].model;
        const std::string limit = "within +-" + format_double(max_counts) + " counts";
        check_range(std::isfinite(m.c1) && std::fabs(m.c1) <= max_counts, where, c,
                    "C1 = " + format_double(m.c1) + " counts, a board takes C1 " + limit);
        check_range(std::isfinite(m.c2) && std::fabs(m.c2) <= max_counts, where, c,
                    "C2 = " + format_double(m.c2) + " counts, a board takes C2 " + limit);
        const double t_ms = std::round(m.t_s * 1000.0);
        check_range(std::isfinite(t_ms) && t_ms >= proto::kCalTMinMs && t_ms <= proto::kCalTMaxMs, where, c,
                    "T = " + format_double(m.t_s) + " s, a board takes T from " +
                        format_double(proto::kCalTMinMs / 1000.0) + " to " + format_double(proto::kCalTMaxMs / 1000.0) +
                        " s");
        out[c] = proto::CalPayload{cal.id,
                                   static_cast<std::uint8_t>(c),
                                   cal.channels[c].zero ? proto::kCalFlagZero : std::uint8_t{0},
                                   to_q8(m.c1),
                                   to_q8(m.c2),
                                   static_cast<std::uint32_t>(t_ms)};
    }
    return out;
}

std::uint16_t content_id(const Calibration& cal) {
    Calibration anonymous = cal;
    anonymous.id = 0;
    std::uint16_t crc = proto::kCrc16Ibm3740Init;
    for (const proto::CalPayload& p : to_payloads(anonymous, cal.source)) {
        std::uint8_t bytes[proto::kCalPayloadSize];
        if (proto::serialize(p, bytes, sizeof bytes) != sizeof bytes) throw Error("CAL payload does not serialize");
        crc = proto::crc16_ibm3740(bytes, sizeof bytes, crc);
    }
    return crc == 0 ? std::uint16_t{1} : crc;
}

}  // namespace driftlab::host::cal
