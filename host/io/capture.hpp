// Raw capture beside each recorded log (LOG.csv.cap): every byte received from the board, every byte sent to
// it, and the recorder's events, time-stamped, so `driftlab decode` rebuilds the log exactly.
// Format: docs/recording.md "Capture format".
//
//   driftlab-capture: 1\n             magic line
//   key: value\n ...                   header (port, baud, start_utc, ...), free text without newlines
//   \n                                 an empty line ends the header
//   records until the end of the file, each:
//     kind   u8   'R' received bytes, 'T' transmitted bytes, 'E' recorder event (text)
//     t_us   u64  little-endian, monotonic microseconds since the capture started
//     len    u32  little-endian, payload bytes
//     payload
//
// Each record goes to the OS in one write(2), so a killed recorder leaves at most one cut record at the end,
// which the reader reports (CaptureReader::truncated_at) and skips. A damaged stretch (a disk or copy fault) is
// skipped to the next place where whole records follow one another again, and reported (CaptureReader::damaged).
#pragma once

#include <chrono>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "host/log/capture_file.hpp"

namespace driftlab::host::io {

enum class CaptureKind : std::uint8_t { rx = 'R', tx = 'T', event = 'E' };

struct CaptureRecord {
    CaptureKind kind = CaptureKind::rx;
    std::uint64_t t_us = 0;  ///< [us] since the capture started
    std::vector<std::uint8_t> payload;
    std::uint64_t offset = 0;  ///< byte offset of the record in the file, for messages
    std::string text() const { return std::string(payload.begin(), payload.end()); }
};

using CaptureHeader = std::vector<std::pair<std::string, std::string>>;

class CaptureWriter {
public:
    /// Creates (truncates) `path` and writes the header. Throws DeviceError when the file cannot be written.
    CaptureWriter(const std::string& path, const CaptureHeader& header);
    ~CaptureWriter();
    CaptureWriter(const CaptureWriter&) = delete;
    CaptureWriter& operator=(const CaptureWriter&) = delete;

    /// Writes one record; returns its t_us, which the live assembler must be given too, so that recording and
    /// `decode` see the same times.
    std::uint64_t write(CaptureKind kind, const std::uint8_t* bytes, std::size_t count);
    std::uint64_t write_event(const std::string& text);
    /// fdatasync(2): every record written so far is on the disk. Throws DeviceError when the OS refuses.
    void sync();
    /// [us] since the capture started (the t_us of a record written now).
    std::uint64_t now_us() const;
    const std::string& path() const { return path_; }

private:
    std::string path_;
    int fd_ = -1;
    std::chrono::steady_clock::time_point start_;
};

class CaptureReader {
public:
    /// Opens `path` and reads the header. Throws DataError(path, line, ...) when it is not a capture.
    explicit CaptureReader(const std::string& path);
    const CaptureHeader& header() const { return header_; }
    std::optional<std::string> header_value(const std::string& key) const;
    /// A stretch of the file that holds no whole record: skipped, so that the records after it are not lost.
    struct Damage {
        std::uint64_t offset = 0;  ///< byte offset where it starts
        std::uint64_t bytes = 0;   ///< its length
    };

    /// The next whole record, or nullopt at the end. A record is whole when its kind is known, its payload lies in
    /// the file, its time neither goes back nor jumps a day ahead (unless a whole record follows it within a day: a
    /// board silent that long in stream mode), and it does not end among bytes that are no
    /// record while whole records start inside it (a damaged length, which would swallow them); where none is, the
    /// reader skips to the next offset where two whole records follow one another (or one ends the file) and notes
    /// the damage.
    std::optional<CaptureRecord> next();
    /// Byte offset of a cut last record (the recorder was killed mid-write), once next() reached it.
    std::optional<std::uint64_t> truncated_at() const { return truncated_at_; }
    /// The damaged stretches skipped so far, in file order.
    const std::vector<Damage>& damaged() const { return damaged_; }
    /// Byte offsets of records whose time was damaged (it jumped ahead of the next record, which follows the one
    /// before): read at the previous record's time.
    const std::vector<std::uint64_t>& retimed() const { return retimed_; }

private:
    /// A day: the longest wait between two records believed on their own (a recorder polling writes every period).
    static constexpr std::uint64_t kMaxStepUs = 86'400'000'000ULL;
    /// A whole record's header at `offset` (its time and length), its payload not copied: what every probe of a
    /// damaged stretch needs, at constant cost.
    struct Probe {
        std::uint64_t t_us = 0;
        std::size_t len = 0;
    };
    std::optional<Probe> probe_at(std::size_t offset, std::uint64_t after_us,
                                  std::uint64_t max_step_us = kMaxStepUs) const;
    std::optional<CaptureRecord> record_at(std::size_t offset, std::uint64_t after_us,
                                           std::uint64_t max_step_us = kMaxStepUs) const;
    bool records_resume_at(std::size_t offset) const;
    /// The first offset at or after `from` where records resume (records_resume_at), or the end of the file. Scans
    /// on from the last answer while the reference time is the same, so that each byte of a damaged stretch is
    /// probed a bounded number of times however the stretch is crafted (a scan from every offset had been quadratic).
    std::size_t first_resume(std::size_t from);
    bool cut_record_at(std::size_t offset) const;
    /// One step of next(): a record, or nullopt having skipped a damaged stretch (more may follow) or reached the end.
    std::optional<CaptureRecord> read_or_skip();

    std::string path_;
    std::vector<std::uint8_t> data_;
    std::size_t pos_ = 0;
    std::uint64_t last_t_us_ = 0;
    CaptureHeader header_;
    std::optional<std::uint64_t> truncated_at_;
    std::vector<Damage> damaged_;
    std::vector<std::uint64_t> retimed_;
    struct ResumeScan {  // first_resume()'s last answer: no resume in [from, at)
        std::size_t from = 0, at = 0;
        std::uint64_t after_us = 0;
        bool valid = false;
    } scan_;
};

}  // namespace driftlab::host::io
