// Recorder: one `driftlab record` session. Opens the port, does the handshake and the configuration, then
// polls (the paper's mode) or listens (stream mode) until the board-time duration is reached or a stop is
// requested; every byte goes to the capture first, then through LogAssembler into the canonical log.
// Losing the port is survived: it is reopened with back-off, the handshake is repeated, and the gap is
// written into the log. docs/recording.md.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "driftlab/proto/messages.hpp"
#include "host/io/log_assembler.hpp"
#include "host/io/status_line.hpp"

namespace driftlab::host::io {

struct RecordOptions {
    std::string port;
    int baud = 115200;
    proto::ConfigPayload config{};  ///< what CONFIG_SET asks for
    double duration_s = 0.0;        ///< [s] of board time (t_s span of the rows); 0 = until stopped
    std::string log_path;
    std::string capture_path;             ///< default: default_capture_path(log_path)
    int reconnect_max_backoff_ms = 4000;  ///< [ms] longest wait between reopen attempts
    std::string recorder_name = "driftlab";
    bool overwrite = false;         ///< replace a log or capture already there (else refused)
    std::optional<CommandKey> key;  ///< the board's command key (docs/security.md); none: an open board
};

/// How the session went, for the final message.
struct RecordSummary {
    AssemblyStats stats;
    std::uint64_t polls_sent = 0;
    std::uint64_t reconnects = 0;
    double wall_s = 0.0;  ///< [s] of wall-clock time
    bool stopped_by_request = false;
};

/// Called four times a second with the progress so far (the live status line), while the port is away too, with
/// `lost` then set.
using RecordProgress = std::function<void(const AssemblyStats&, double wall_s, const std::optional<LinkLoss>& lost)>;

/// Runs the session. Makes the folders of the log and the capture when missing, then opens the port. Throws
/// DeviceError when a folder cannot be made or a file not written there (before the port is opened), when the port
/// cannot be opened or the device is not a driftlab board of this protocol version (nothing is left behind then,
/// not even the folders it made), UsageError/DeviceError from the log writer, and DeviceError after finishing the
/// log and capture when the board refuses a POLL (BoardClient::poll_refusal: it is streaming after all).
RecordSummary record(const RecordOptions& options, const std::atomic<bool>& stop, const RecordProgress& progress);

/// The current UTC time as ISO 8601 with milliseconds ("2026-11-22T10:00:00.123Z").
std::string utc_now_iso8601();

}  // namespace driftlab::host::io
