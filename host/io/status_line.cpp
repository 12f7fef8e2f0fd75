// Status line formatting (status_line.hpp).
#include "host/io/status_line.hpp"

#include <cstdio>

#include "host/util/format_number.hpp"
#include "host/util/units.hpp"

namespace driftlab::host::io {

double loss_percent(const AssemblyStats& s) {
    const double sent = static_cast<double>(s.frames - s.duplicate_frames + s.lost_frames);
    return sent > 0.0 ? 100.0 * static_cast<double>(s.lost_frames) / sent : 0.0;
}

std::string format_status_line(const AssemblyStats& s, double wall_s, const std::optional<LinkLoss>& lost) {
    char text[256];
    int n = std::snprintf(text, sizeof text, "%7.1f s  rows %llu  lost %llu (%.2f %%)", wall_s,
                          static_cast<unsigned long long>(s.rows), static_cast<unsigned long long>(s.lost_frames),
                          loss_percent(s));
    if (lost) {
        std::snprintf(text + n, sizeof text - static_cast<std::size_t>(n),
                      "  PORT LOST %.1f s ago, reconnect attempt %d in %.1f s", lost->lost_for_s, lost->next_attempt,
                      lost->next_attempt_in_s);
        return text;
    }
    if (s.rows > 0) {
        const auto& c = s.last_counts;
        const double mid = kMidScaleCode;
        // The accelerometer in counts: a level from mid-scale is no acceleration (accel_z's mid-scale is 1 g, each
        // axis has its zero-g offset), and a g figure from mid-scale had shown a board at rest reading 2 g on Z.
        std::snprintf(text + n, sizeof text - static_cast<std::size_t>(n),
                      "  gyro %+.2f deg/s  accel %.1f %.1f %.1f counts  dropped %u", (c[0] - mid) * kGyroDpsPerCount,
                      c[1], c[2], c[3], static_cast<unsigned>(s.last_dropped));
    }
    return text;
}

std::string link_lost_gap(const std::optional<double>& last_t_s, double lost_at_s, double away_s, int attempts) {
    return "link lost " +
           (last_t_s ? "after t_s=" + fixed_point(*last_t_s, 3) + " (board clock)"
                     : std::string("before the first row")) +
           ", " + fixed_point(lost_at_s, 3) + " s into the recording (host clock); reconnected after " +
           fixed_point(away_s, 3) + " s (host clock), " + counted(static_cast<std::size_t>(attempts), "attempt");
}

std::string skipped_samples(const AssemblyStats& stats) {
    const std::uint64_t skipped = stats.stale_samples + stats.unreachable_samples + stats.empty_samples;
    if (skipped == 0) return "";
    return "skipped " + counted(skipped, "sample") + ": " + std::to_string(stats.stale_samples) +
           " repeated (time not after the previous row), " + std::to_string(stats.unreachable_samples) +
           " beyond the converter's reach, " + std::to_string(stats.empty_samples) +
           " of an empty window (just after a CONFIG restarted the windows)";
}

std::string untrusted_frames(const AssemblyStats& stats) {
    std::string out;
    if (stats.conflicting_frames > 0)
        out += std::to_string(stats.conflicting_frames) +
               (stats.conflicting_frames == 1 ? " shared its seq" : " shared their seq") +
               " with another of other content (neither used; " + counted(stats.conflicting_rows, "row") + " kept out)";
    if (stats.unexpected_versions + stats.unexpected_configs > 0)
        out += (out.empty() ? "" : ", ") + std::to_string(stats.unexpected_versions) + " VERSION and " +
               std::to_string(stats.unexpected_configs) +
               " CONFIG differing from the handshake's ignored (each noted in the log)";
    if (stats.foreign_config_acks > 0)
        out += (out.empty() ? "" : ", ") +
               std::string(
                   "an ACK of a CONFIG_SET or CAL_SET the recording did not send (the board was "
                   "reconfigured by someone else: no row after it)");
    else if (stats.other_window_samples > 0)
        out += (out.empty() ? "" : ", ") + std::string(
                                               "a SAMPLE of a window the recording did not set (the board was "
                                               "reconfigured or restarted: no row after it)");
    else if (stats.other_calibration_samples > 0)
        out += (out.empty() ? "" : ", ") + std::string(
                                               "a SAMPLE of a calibration the handshake did not report (a "
                                               "calibration uploaded or a warm restart: no row after it)");
    return out.empty() ? out : "untrusted frames: " + out;
}

}  // namespace driftlab::host::io
