// LogWriter; see log_writer.hpp and docs/log-format.md.
#include "host/log/log_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "host/log/log_data.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"

namespace driftlab::host {

LogWriter::LogWriter(const std::string& path, const LogMetadata& metadata, std::vector<std::string> optional_columns)
    : path_(path), optional_columns_(std::move(optional_columns)) {
    for (const auto& name : optional_columns_) {
        const bool known = std::any_of(kOptionalLogColumns.begin(), kOptionalLogColumns.end(),
                                       [&](const char* k) { return name == k; });
        if (!known) throw UsageError("log column '" + name + "' is not an optional column of log format v1");
        if (std::count(optional_columns_.begin(), optional_columns_.end(), name) > 1)
            throw UsageError("log column '" + name + "' named twice");
    }
    if (path_ == "-") {
        fd_ = STDOUT_FILENO;
    } else {
        fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        if (fd_ < 0) throw DeviceError(path_, std::string("cannot open for writing: ") + std::strerror(errno));
        owns_fd_ = true;
    }
    if (const auto bits = metadata.get_int("adc_bits")) range_ = converter_range(*bits);
    pending_ = "# driftlab-log: " + std::to_string(kLogFormatVersion) + "\n";
    for (const auto& [key, value] : metadata.entries()) pending_ += "# " + key + ": " + value + "\n";
    for (std::size_t i = 0; i < kRequiredLogColumns.size(); ++i) {
        if (i) pending_ += ',';
        pending_ += kRequiredLogColumns[i];
    }
    for (const auto& name : optional_columns_) pending_ += "," + name;
    pending_ += '\n';
    flush();
}

LogWriter::~LogWriter() {
    try {
        close();
    } catch (const Error&) {
        // A destructor cannot report; close() is the way to see write errors.
    }
}

void LogWriter::write_row(const LogRow& row) {
    if (row.optional_values.size() != optional_columns_.size())
        throw UsageError("log row has " + std::to_string(row.optional_values.size()) + " optional values, header has " +
                         std::to_string(optional_columns_.size()));
    const auto finite = [](double v) { return std::isfinite(v); };
    if (!std::isfinite(row.t_s) || !std::all_of(row.counts.begin(), row.counts.end(), finite) ||
        !std::all_of(row.optional_values.begin(), row.optional_values.end(), finite))
        throw UsageError("log row at t_s=" + format_double(row.t_s) + " has a NaN or infinite value");
    for (std::size_t c = 0; range_ && c < kChannelCount; ++c)
        if (!range_->holds_estimate(row.counts[c]))
            throw UsageError("log row at t_s=" + format_double(row.t_s) + " has " + kChannelNames[c] + " = " +
                             format_double(row.counts[c]) + " counts, beyond the converter's reach (" +
                             format_double(range_->estimate_low()) + " to " + format_double(range_->estimate_high()) +
                             ")");
    for (std::size_t i = 0; range_ && i < optional_columns_.size(); ++i)
        if (is_raw_code_column(optional_columns_[i]) && !range_->holds_raw_code(row.optional_values[i]))
            throw UsageError("log row at t_s=" + format_double(row.t_s) + " has " + optional_columns_[i] + " = " +
                             format_double(row.optional_values[i]) + ", not a code of the converter");
    if (row.t_s < 0.0) throw UsageError("log row t_s=" + format_double(row.t_s) + " is before power-on");
    if (rows_ > 0 && !(row.t_s > last_t_s_))
        throw UsageError("log row t_s=" + format_double(row.t_s) +
                         " does not follow the previous t_s=" + format_double(last_t_s_));
    append_double(pending_, row.t_s);
    pending_ += ',';
    pending_ += std::to_string(row.seq);
    for (double v : row.counts) {
        pending_ += ',';
        append_double(pending_, v);
    }
    for (double v : row.optional_values) {
        pending_ += ',';
        append_double(pending_, v);
    }
    last_t_s_ = row.t_s;
    ++rows_;
    append_line_end();
}

void LogWriter::write_gap(const std::string& text) { write_event_line("gap", text); }

void LogWriter::write_unexpected(const std::string& text) { write_event_line("unexpected", text); }

void LogWriter::write_event_line(const std::string& kind, const std::string& text) {
    if (text.find_first_of("\r\n") != std::string::npos)
        throw UsageError("log " + kind + " text contains a line break");
    pending_ += "# " + kind + ": " + text;
    append_line_end();
}

void LogWriter::append_line_end() {
    pending_ += '\n';
    const auto now = std::chrono::steady_clock::now();
    if (now - last_flush_ >= flush_interval_) flush();
}

void LogWriter::flush() {
    if (fd_ < 0) return;
    std::size_t done = 0;
    while (done < pending_.size()) {
        const ssize_t n = ::write(fd_, pending_.data() + done, pending_.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            const int error = errno;
            // A full disk or a file-size limit can take part of the lines: cut the file back to its last whole line,
            // so that the log stays readable (a regular file; a pipe keeps what it took).
            if (done > 0 && owns_fd_ && ::ftruncate(fd_, static_cast<off_t>(written_)) == 0)
                static_cast<void>(::lseek(fd_, static_cast<off_t>(written_), SEEK_SET));
            throw DeviceError(path_, std::string("cannot write log: ") + std::strerror(error));
        }
        done += static_cast<std::size_t>(n);
    }
    written_ += pending_.size();
    pending_.clear();
    last_flush_ = std::chrono::steady_clock::now();
}

void LogWriter::sync() {
    flush();
    if (fd_ >= 0 && ::fdatasync(fd_) != 0 && errno != EINVAL)  // EINVAL: a pipe or terminal, nothing to sync
        throw DeviceError(path_, std::string("cannot sync log to disk: ") + std::strerror(errno));
}

void LogWriter::close() {
    if (fd_ < 0) return;
    try {
        flush();
    } catch (const DeviceError&) {
        if (owns_fd_) ::close(fd_);
        fd_ = -1;
        throw;
    }
    if (owns_fd_ && ::close(fd_) != 0) {
        fd_ = -1;
        throw DeviceError(path_, std::string("cannot close log: ") + std::strerror(errno));
    }
    fd_ = -1;
}

}  // namespace driftlab::host
