// Reads a canonical log (docs/log-format.md) into LogData, or throws DataError(file, line, what).
//
// Accepted: `# driftlab-log: 1`, `# key: value` metadata, a header holding at least
// t_s,seq,gyro,accel_x,accel_y,accel_z (any order; optional columns kept, unknown ones ignored), rows with
// exactly the header's field count, `# gap: text` events and other `#` comments between rows, blank lines.
// Rejected, with the line number: a missing or repeated header, a wrong field count, a value that is not
// a finite number, a t_s not strictly after the previous row's, a non-integer seq, an empty file, a log
// without rows, and an unterminated last line (unless ReadOptions::drop_truncated_tail, the commands'
// --drop-cut-line; the refusal names that option, and the `driftlab decode` command of the recording's capture, found
// beside the log by its metadata's `capture` name or record's default name).
#pragma once

#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "host/log/log_data.hpp"

namespace driftlab::host {

struct ReadOptions {
    /// Drop a last line without '\n' (a recorder killed mid-write) instead of rejecting the file.
    bool drop_truncated_tail = false;
    /// Converter resolution to hold the channel values to when the metadata names no `adc_bits` (a reader that
    /// goes on to simulate that converter, as `gap` does, cannot take values it never makes).
    std::optional<int> assumed_adc_bits;
};

/// Reads the log at `path`. Throws DataError for malformed content, DataError(path, 0, ...) when unreadable.
LogData read_log(const std::string& path, const ReadOptions& options = {});

/// Parses a log from `in`; `source_name` is used in messages.
LogData parse_log(std::istream& in, const std::string& source_name, const ReadOptions& options = {});

/// What a command says when it dropped a cut last line (ReadOptions::drop_truncated_tail): "LOG:N: ..." naming the
/// line, so that the row left out is never a silent loss; "" when the log had none.
std::string dropped_cut_line_note(const LogData& log);

/// Whether `in` holds a canonical log: its first line that is not blank is the magic line as read_log() takes it
/// (`# driftlab-log: N`, any version, blanks around the key allowed), or a comment naming `driftlab-log` (a damaged
/// magic line, which read_log() then refuses). Reads from the stream's position.
bool starts_as_log(std::istream& in);

/// The key and value of a comment's body (the text after `#`) of the form `key: value`, blanks trimmed; none where
/// there is no colon or the key is empty or holds a blank (free text).
std::optional<std::pair<std::string, std::string>> split_comment_key_value(std::string_view body);

}  // namespace driftlab::host
