// Opening a file a command reads: one place that says why it cannot be read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

namespace driftlab::host {

/// Opens `path` for binary reading. Throws DataError(path, 0, ...) when it is missing or unreadable (the system's
/// reason) or a folder (which a stream opens, and then reads as an empty file).
std::ifstream open_input_file(const std::string& path);

/// The longest line a log, table or capture header may have [bytes]: 16 MiB holds a recording of some 1.6 million
/// numbers written on one line (loggers that do exist: a 2 MB one-line gyro record is among the project's real
/// data); a longer line is refused before it is held.
inline constexpr std::size_t kMaxLineBytes = std::size_t{16} << 20;

/// Throws the DataError(path, line, ...) of a line longer than kMaxLineBytes.
[[noreturn]] void refuse_long_line(const std::string& path, std::uint64_t line);

/// std::getline for untrusted text: false at the end; throws DataError(path, line, ...) for a line of more than
/// kMaxLineBytes, having read no more than that of it. `ended` tells whether the line ended with '\n' (not cut).
bool read_line(std::istream& in, std::string& text, const std::string& path, std::uint64_t line, bool* ended = nullptr);

/// The largest JSON file a command reads whole (fit, allan and nav --json output, read by nav --drift and report --nav)
/// [bytes]: theirs are kilobytes; a parsed JSON document takes several times its text.
inline constexpr std::size_t kMaxJsonFileBytes = std::size_t{16} << 20;

/// The whole of `path`, a file a command reads at once (a JSON document). Throws DataError(path, 0, ...) naming the
/// limit when it holds more than `max_bytes`, having read no more than that of it.
std::string read_small_file(const std::string& path, std::size_t max_bytes);

}  // namespace driftlab::host
