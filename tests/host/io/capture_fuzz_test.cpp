// The capture reader on randomly damaged captures (deterministic seeds; docs/recording.md "Capture format"):
//   - every byte after the header is accounted for: whole records, damaged stretches and a cut last record;
//   - records come in file order, their times never going back;
//   - no good data is lost: a record left whole, with the record after it whole too (or the file ending after it), is
//     read at its offset with its kind, time and payload.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "host/io/capture.hpp"

namespace fs = std::filesystem;
using namespace driftlab::host::io;

namespace {

constexpr std::size_t kRecordHeader = 13;  // kind u8, t_us u64, len u32

struct Written {
    std::string bytes;                 // the whole file
    std::size_t header_size = 0;       // up to and with the empty line
    std::vector<std::size_t> offsets;  // of each record
    std::vector<std::size_t> sizes;    // of each record, its header included
};

// 200 records of random kind and 1 to 40 payload bytes; the payloads are rich in kind letters, so that damage often
// leaves bytes that look like a record's start.
Written write_capture(const std::string& path, std::mt19937& rng) {
    Written w;
    {
        CaptureWriter writer(path, {{"port", "/dev/ttyUSB0"}, {"baud", "115200"}});
        w.header_size = static_cast<std::size_t>(fs::file_size(path));
        const CaptureKind kinds[] = {CaptureKind::rx, CaptureKind::tx, CaptureKind::event};
        for (int k = 0; k < 200; ++k) {
            std::vector<std::uint8_t> payload(1 + rng() % 40);
            for (auto& b : payload)
                b = rng() % 4 == 0 ? static_cast<std::uint8_t>("RTE"[rng() % 3]) : static_cast<std::uint8_t>(rng());
            w.offsets.push_back(static_cast<std::size_t>(fs::file_size(path)));
            w.sizes.push_back(kRecordHeader + payload.size());
            writer.write(kinds[rng() % 3], payload.data(), payload.size());
        }
    }
    std::ifstream in(path, std::ios::binary);
    w.bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return w;
}

TEST(CaptureFuzz, DamagedCapturesAccountForEveryByteAndLoseNoWholeRecord) {
    const std::string path =
        (fs::temp_directory_path() / ("driftlab_capfuzz_" + std::to_string(::getpid()) + ".cap")).string();
    std::mt19937 rng(2026);
    const Written clean = write_capture(path, rng);
    const std::size_t records = clean.offsets.size();
    std::size_t checked_whole = 0, damaged_stretches = 0, cut = 0;
    for (int trial = 0; trial < 400; ++trial) {
        std::string bytes = clean.bytes;
        std::vector<bool> touched(bytes.size(), false);
        // In place, so that every record keeps its offset: runs of 1 to 20 bytes overwritten.
        for (int e = 1 + static_cast<int>(rng() % 6); e > 0; --e) {
            const std::size_t at = clean.header_size + rng() % (bytes.size() - clean.header_size);
            for (std::size_t i = at, end = std::min(bytes.size(), at + 1 + rng() % 20); i < end; ++i) {
                const char was = bytes[i];
                bytes[i] = static_cast<char>(rng());
                touched[i] = touched[i] || bytes[i] != was;
            }
        }
        // Sometimes the recorder was killed: the file ends inside a record.
        std::size_t size = bytes.size();
        if (rng() % 4 == 0) {
            size = clean.header_size + rng() % (bytes.size() - clean.header_size);
            bytes.resize(size);
        }
        std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;

        CaptureReader reader(path);
        std::vector<CaptureRecord> read;
        while (auto rec = reader.next()) read.push_back(*rec);

        std::size_t accounted = clean.header_size;
        for (std::size_t i = 0; i < read.size(); ++i) {
            accounted += kRecordHeader + read[i].payload.size();
            if (i > 0) {
                EXPECT_GT(read[i].offset, read[i - 1].offset);
                EXPECT_GE(read[i].t_us, read[i - 1].t_us);
            }
        }
        for (const auto& d : reader.damaged()) accounted += d.bytes;
        damaged_stretches += reader.damaged().size();
        if (reader.truncated_at()) {
            ++cut;
            accounted += size - *reader.truncated_at();
        }
        EXPECT_EQ(accounted, size) << "trial " << trial;

        const auto whole = [&](std::size_t r) {
            if (clean.offsets[r] + clean.sizes[r] > size) return false;
            for (std::size_t i = clean.offsets[r]; i < clean.offsets[r] + clean.sizes[r]; ++i)
                if (touched[i]) return false;
            return true;
        };
        for (std::size_t r = 0; r < records; ++r) {
            const bool last_in_file = clean.offsets[r] + clean.sizes[r] == size;
            if (!whole(r) || !(last_in_file || (r + 1 < records && whole(r + 1)))) continue;
            ++checked_whole;
            const auto at = std::find_if(read.begin(), read.end(),
                                         [&](const CaptureRecord& c) { return c.offset == clean.offsets[r]; });
            ASSERT_NE(at, read.end()) << "trial " << trial << ": whole record " << r << " at byte " << clean.offsets[r]
                                      << " not read";
            EXPECT_EQ(at->payload.size() + kRecordHeader, clean.sizes[r]);
            EXPECT_EQ(std::string(at->payload.begin(), at->payload.end()),
                      clean.bytes.substr(clean.offsets[r] + kRecordHeader, clean.sizes[r] - kRecordHeader));
            EXPECT_EQ(static_cast<char>(at->kind), clean.bytes[clean.offsets[r]]);
            std::uint64_t t_us = 0;
            for (int b = 7; b >= 0; --b)
                t_us = t_us << 8 |
                       static_cast<std::uint8_t>(clean.bytes[clean.offsets[r] + 1 + static_cast<std::size_t>(b)]);
            EXPECT_EQ(at->t_us, t_us);
        }
    }
    // The damage above reached the reader's every path.
    EXPECT_GT(checked_whole, 40000u);
    EXPECT_GT(damaged_stretches, 300u);
    EXPECT_GT(cut, 30u);
    fs::remove(path);
}

}  // namespace
