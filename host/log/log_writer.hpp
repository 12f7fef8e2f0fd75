// Writes a canonical log (docs/log-format.md): magic line, metadata, header, then rows and gap events.
//
// How to use: construct with the path ("-" = standard output), the metadata and the optional columns you
// will fill; the first three parts are written at once. Then call write_row() per sample and write_gap()
// when the link was lost. Lines are collected in memory and handed to the OS whole, each flush writing
// only complete lines, so a reader of a growing file never sees a torn line unless the process dies
// inside write(2). flush() forces the pending lines out; the destructor flushes (errors are then lost:
// call close() to see them).
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "driftlab/channels.hpp"
#include "host/log/log_data.hpp"
#include "host/log/log_metadata.hpp"

namespace driftlab::host {

/// One sample: the required columns plus values for the optional columns given to the constructor.
struct LogRow {
    double t_s = 0.0;                            ///< [s] since power-on
    std::uint64_t seq = 0;                       ///< unwrapped frame sequence number
    std::array<double, kChannelCount> counts{};  ///< [counts] per Channel
    std::vector<double> optional_values;         ///< same order as the writer's optional columns
};

class LogWriter {
public:
    /// Opens `path` for writing (truncating it) and writes magic, metadata and header.
    /// `optional_columns` must come from kOptionalLogColumns. Throws UsageError on bad names,
    /// DeviceError when the file cannot be opened or written.
    LogWriter(const std::string& path, const LogMetadata& metadata, std::vector<std::string> optional_columns = {});
    ~LogWriter();
    LogWriter(const LogWriter&) = delete;
    LogWriter& operator=(const LogWriter&) = delete;

    /// Pending lines are written when this much time has passed since the last flush; zero = every line.
    void set_flush_interval(std::chrono::milliseconds interval) { flush_interval_ = interval; }

    /// Appends one row. Throws UsageError on NaN/inf, a channel value beyond the converter's reach or a raw code it
    /// cannot make (when the metadata holds `adc_bits`), a t_s not after the previous one, or a wrong number of
    /// optional values: the writer never produces a file its reader rejects.
    void write_row(const LogRow& row);
    /// Appends `# gap: text` (text without newlines).
    void write_gap(const std::string& text);
    /// `# unexpected: text` among the rows: a frame the recording ignored (docs/log-format.md §5).
    void write_unexpected(const std::string& text);

    /// Writes all pending lines. Throws DeviceError when the OS refuses.
    void flush();
    /// flush(), then fdatasync(2): the lines are on the disk, not only with the OS (a recording's each second, so
    /// that a power loss of the PC costs at most that second). Throws DeviceError when the OS refuses either.
    void sync();
    /// Flushes and closes; later calls do nothing.
    void close();

private:
    void write_event_line(const std::string& kind, const std::string& text);
    void append_line_end();

    std::string path_;
    int fd_ = -1;
    bool owns_fd_ = false;
    std::uint64_t written_ = 0;  // bytes handed to the OS, every one in whole lines
    std::vector<std::string> optional_columns_;
    std::string pending_;
    std::chrono::milliseconds flush_interval_{1000};
    std::chrono::steady_clock::time_point last_flush_;
    std::uint64_t rows_ = 0;
    double last_t_s_ = 0.0;
    std::optional<ConverterRange> range_;  // from the metadata's adc_bits
};

}  // namespace driftlab::host
