// Capture file writer and reader (format in capture.hpp and docs/recording.md).
#include "host/io/capture.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string_view>

#include "host/log/capture_file.hpp"
#include "host/log/log_metadata.hpp"
#include "host/util/error.hpp"
#include "host/util/input_file.hpp"

namespace driftlab::host::io {
namespace {

constexpr std::size_t kRecordHeaderSize = 1 + 8 + 4;

bool known_kind(std::uint8_t kind) {
    return kind == static_cast<std::uint8_t>(CaptureKind::rx) || kind == static_cast<std::uint8_t>(CaptureKind::tx) ||
           kind == static_cast<std::uint8_t>(CaptureKind::event);
}

constexpr char kMagic[] = "driftlab-capture: 1";  // the format version is the magic line's number

void put_le(std::string& out, std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
}

std::uint64_t get_le(const std::uint8_t* p, int bytes) {
    std::uint64_t v = 0;
    for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | p[i];
    return v;
}

void write_all(int fd, const std::string& data, const std::string& path) {
    std::size_t done = 0;
    while (done < data.size()) {
        const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw DeviceError(path, std::string("cannot write the capture: ") + std::strerror(errno));
        }
        done += static_cast<std::size_t>(n);
    }
}

}  // namespace

CaptureWriter::CaptureWriter(const std::string& path, const CaptureHeader& header)
    : path_(path), start_(std::chrono::steady_clock::now()) {
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd_ < 0) throw DeviceError(path, std::string("cannot create the capture: ") + std::strerror(errno));
    std::string text = std::string(kMagic) + "\n";
    for (const auto& [key, value] : header) text += key + ": " + value + "\n";
    text += "\n";
    write_all(fd_, text, path_);
}

CaptureWriter::~CaptureWriter() {
    if (fd_ >= 0) ::close(fd_);
}

std::uint64_t CaptureWriter::now_us() const {
    return static_cast<std::uint64_t>(
        std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start_).count());
}

void CaptureWriter::sync() {
    if (fd_ >= 0 && ::fdatasync(fd_) != 0 && errno != EINVAL)
        throw DeviceError(path_, std::string("cannot sync capture to disk: ") + std::strerror(errno));
}

std::uint64_t CaptureWriter::write(CaptureKind kind, const std::uint8_t* bytes, std::size_t count) {
    const std::uint64_t t_us = now_us();
    std::string record;
    record.reserve(kRecordHeaderSize + count);
    record.push_back(static_cast<char>(kind));
    put_le(record, t_us, 8);
    put_le(record, count, 4);
    record.append(reinterpret_cast<const char*>(bytes), count);
    write_all(fd_, record, path_);
    return t_us;
}

std::uint64_t CaptureWriter::write_event(const std::string& text) {
    return write(CaptureKind::event, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
}

CaptureReader::CaptureReader(const std::string& path) : path_(path) {
    std::ifstream in = open_input_file(path);
    data_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    std::uint64_t line = 0;
    bool ended = false;
    while (pos_ < data_.size()) {
        const auto nl = std::find(data_.begin() + static_cast<std::ptrdiff_t>(pos_), data_.end(), '\n');
        if (nl == data_.end()) break;
        const std::string text(data_.begin() + static_cast<std::ptrdiff_t>(pos_), nl);
        pos_ = static_cast<std::size_t>(nl - data_.begin()) + 1;
        ++line;
        if (line == 1) {
            if (text.rfind(kCaptureMagicKey, 0) == 0 && text != kMagic)
                throw DataError(path, 1,
                                "capture format version '" + text.substr(kCaptureMagicKey.size()) +
                                    "' is not supported (this reader knows 1)");
            if (text != kMagic)
                throw DataError(path, 1, "not a driftlab capture (expected '" + std::string(kMagic) + "')");
            continue;
        }
        if (text.empty()) {
            ended = true;
            break;
        }
        const std::size_t colon = text.find(": ");
        if (colon == std::string::npos) throw DataError(path, line, "header line without 'key: value'");
        // Its keys become the log's metadata keys: a damaged one is the capture's fault, named here.
        if (!LogMetadata::is_valid_key(text.substr(0, colon)))
            throw DataError(path, line, "header key '" + text.substr(0, colon) + "' is not lower_snake_case");
        if (!LogMetadata::is_valid_value(text.substr(colon + 2)))
            throw DataError(path, line, "header value of '" + text.substr(0, colon) + "' holds a carriage return");
        header_.emplace_back(text.substr(0, colon), text.substr(colon + 2));
    }
    if (line == 0) throw DataError(path, 1, "not a driftlab capture (empty or no magic line)");
    if (!ended) throw DataError(path, line, "capture header not terminated by an empty line");
}

std::optional<std::string> CaptureReader::header_value(const std::string& key) const {
    for (const auto& [k, v] : header_) {
        if (k == key) return v;
    }
    return std::nullopt;
}

std::optional<CaptureReader::Probe> CaptureReader::probe_at(std::size_t offset, std::uint64_t after_us,
                                                            std::uint64_t max_step_us) const {
    if (data_.size() - offset < kRecordHeaderSize) return std::nullopt;
    const std::uint8_t* p = data_.data() + offset;
    if (!known_kind(p[0])) return std::nullopt;
    const std::uint64_t t_us = get_le(p + 1, 8);
    const std::uint64_t len = get_le(p + 9, 4);
    if (t_us < after_us || t_us - after_us > max_step_us || data_.size() - offset - kRecordHeaderSize < len)
        return std::nullopt;
    return Probe{t_us, static_cast<std::size_t>(len)};
}

std::optional<CaptureRecord> CaptureReader::record_at(std::size_t offset, std::uint64_t after_us,
                                                      std::uint64_t max_step_us) const {
    const auto probe = probe_at(offset, after_us, max_step_us);
    if (!probe) return std::nullopt;
    CaptureRecord rec;
    rec.kind = static_cast<CaptureKind>(data_[offset]);
    rec.t_us = probe->t_us;
    rec.offset = offset;
    const std::uint8_t* p = data_.data() + offset + kRecordHeaderSize;
    rec.payload.assign(p, p + probe->len);
    return rec;
}

bool CaptureReader::records_resume_at(std::size_t offset) const {
    const auto first = probe_at(offset, last_t_us_);
    if (!first) return false;
    const std::size_t end = offset + kRecordHeaderSize + first->len;
    return end == data_.size() || probe_at(end, first->t_us).has_value();
}

std::size_t CaptureReader::first_resume(std::size_t from) {
    const bool same = scan_.valid && scan_.after_us == last_t_us_;
    if (same && from >= scan_.from && from <= scan_.at) return scan_.at;
    std::size_t k = from;
    while (k < data_.size() && !records_resume_at(k)) {
        ++k;
        if (same && k == scan_.from) {  // joined the last scan: its answer holds
            k = scan_.at;
            break;
        }
    }
    scan_ = {from, k, last_t_us_, true};
    return k;
}

// A record of a known kind that runs past the end of the file: the recorder was killed while writing it.
bool CaptureReader::cut_record_at(std::size_t offset) const {
    if (!known_kind(data_[offset])) return false;
    const std::size_t left = data_.size() - offset;
    return left < kRecordHeaderSize || left - kRecordHeaderSize < get_le(data_.data() + offset + 9, 4);
}

std::optional<CaptureRecord> CaptureReader::next() {
    // A loop, not a recursion per damaged stretch: a crafted capture of a million stretches had no stack for it.
    while (pos_ < data_.size() && !truncated_at_)
        if (auto rec = read_or_skip()) return rec;
    return std::nullopt;
}

std::optional<CaptureRecord> CaptureReader::read_or_skip() {
    // A stream-mode recorder writes nothing while the board is silent: a record more than a day after the last is
    // believed where a whole record follows it within a day (a damaged time is followed by none).
    auto rec = record_at(pos_, last_t_us_);
    const bool in_a_day = rec.has_value();
    if (!in_a_day) rec = record_at(pos_, last_t_us_, std::numeric_limits<std::uint64_t>::max());
    if (rec) {
        const std::size_t end = pos_ + kRecordHeaderSize + rec->payload.size();
        const bool at_end = end == data_.size();
        const bool followed = !at_end && probe_at(end, rec->t_us).has_value();
        if (!in_a_day && !followed) rec.reset();
        // A damaged time that jumps ahead: the next record does not follow it but follows the one before. Read at the
        // previous record's time, so that its time does not become the reference every later record falls behind.
        const bool retimed = rec && in_a_day && !at_end && !followed && probe_at(end, last_t_us_).has_value();
        if (retimed) {
            rec->t_us = last_t_us_;
            retimed_.push_back(pos_);
        }
        // A damaged length swallows the records after it: its end then falls among bytes that are no record, while
        // whole records start inside what it claims. (A whole record followed by damage has none inside.)
        if (rec && in_a_day && !at_end && !followed && !retimed && !cut_record_at(end) &&
            first_resume(pos_ + kRecordHeaderSize) < end)
            rec.reset();
    }
    if (rec) {
        pos_ += kRecordHeaderSize + rec->payload.size();
        last_t_us_ = rec->t_us;
        return rec;
    }
    const std::size_t resume = first_resume(pos_ + 1);
    if (resume == data_.size() && known_kind(data_[pos_])) {
        // Nothing whole follows: a record cut by a kill (its kind known, its length past the end).
        truncated_at_ = pos_;
        return std::nullopt;
    }
    damaged_.push_back({pos_, resume - pos_});
    pos_ = resume;
    return std::nullopt;
}

}  // namespace driftlab::host::io
