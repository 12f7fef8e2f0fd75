// What the log readers know of a raw capture (host/io/capture.hpp, docs/recording.md): where `record` puts it beside
// a log, and its magic line, so that a reader names `decode` for a capture instead of failing on it as a table.
#pragma once

#include <istream>
#include <string>
#include <string_view>

namespace driftlab::host {

/// A capture's magic line up to its format version ("driftlab-capture: 1").
inline constexpr std::string_view kCaptureMagicKey = "driftlab-capture: ";

/// Where `record` writes the capture of the log at `log_path` unless given --capture: beside it, LOG.csv.cap.
std::string default_capture_path(const std::string& log_path);

/// True when `in` opens with a capture's magic line, of any format version. Reads the first line from the stream's
/// position.
bool starts_as_capture(std::istream& in);

}  // namespace driftlab::host
