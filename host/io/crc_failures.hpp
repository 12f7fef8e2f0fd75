// Where a capture's frames failed their CRC check, record by record, as `decode` reports them: "byte offset N"
// notes (a damaged copy of the file, or a noisy link the live log lost them to as well).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace driftlab::host::io {

/// Fed after every record with the decoder's running count of CRC failures: the warning names the first few records
/// and counts the rest, json() lists them all.
class CrcFailures {
public:
    void after_record(std::uint32_t bad_crc_so_far, std::uint64_t record_offset) {
        if (bad_crc_so_far > seen_) records_.push_back({record_offset, bad_crc_so_far - seen_});
        seen_ = bad_crc_so_far;
    }
    /// One "driftlab: warning:" line on the error output; nothing when no frame failed.
    void warn(const std::string& capture) const;
    /// [{"offset": record's byte offset, "frames": failures in it}, ...] in file order.
    nlohmann::json json() const;
    std::uint32_t frames() const { return seen_; }

private:
    static constexpr std::size_t kNamed = 5;
    struct Located {
        std::uint64_t offset = 0;  ///< of the record whose bytes completed the failing frames
        std::uint32_t frames = 0;
    };
    std::uint32_t seen_ = 0;
    std::vector<Located> records_;
};

}  // namespace driftlab::host::io
