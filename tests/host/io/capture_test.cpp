// Capture file: records round-trip, a cut last record is reported with its offset, a damaged stretch is skipped to
// the records after it, bad input names its place.
#include "host/io/capture.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <filesystem>
#include <fstream>

#include "host/util/error.hpp"

namespace fs = std::filesystem;
using namespace driftlab::host;
using namespace driftlab::host::io;

namespace {

std::string temp_file(const std::string& name) {
    return (fs::temp_directory_path() / ("driftlab_cap_" + std::to_string(::getpid()) + "_" + name)).string();
}

// Six records of 7 frame-like bytes (a kind letter among them; the second is k), received and sent in turn; their
// offsets.
std::vector<std::uint64_t> six_records(const std::string& path) {
    std::vector<std::uint64_t> offsets;
    CaptureWriter w(path, {{"port", "/dev/pts/3"}});
    for (std::uint8_t k = 0; k < 6; ++k) {
        offsets.push_back(fs::file_size(path));
        const std::uint8_t bytes[7] = {0x7e, k, 'R', 0, 0, 0, k};
        w.write(k % 2 ? CaptureKind::tx : CaptureKind::rx, bytes, sizeof bytes);
    }
    return offsets;
}

// The offsets of the records `r` reads, to its end.
std::vector<std::uint64_t> offsets_read(CaptureReader& r) {
    std::vector<std::uint64_t> out;
    while (auto rec = r.next()) out.push_back(rec->offset);
    return out;
}

}  // namespace

TEST(Capture, RecordsAndHeaderRoundTrip) {
    const std::string path = temp_file("rt.cap");
    {
        CaptureWriter w(path, {{"port", "/dev/ttyUSB0"}, {"baud", "115200"}});
        const std::uint8_t rx[] = {0xD7, 0x1A, 0x01, 0x00, 0x0A};
        w.write(CaptureKind::rx, rx, sizeof rx);
        w.write_event("start");
        w.write(CaptureKind::tx, rx, 0);
    }
    CaptureReader r(path);
    EXPECT_EQ(r.header_value("port"), "/dev/ttyUSB0");
    EXPECT_EQ(r.header_value("baud"), "115200");
    auto a = r.next();
    ASSERT_TRUE(a);
    EXPECT_EQ(a->kind, CaptureKind::rx);
    EXPECT_EQ(a->payload, (std::vector<std::uint8_t>{0xD7, 0x1A, 0x01, 0x00, 0x0A}));
    auto b = r.next();
    ASSERT_TRUE(b);
    EXPECT_EQ(b->text(), "start");
    EXPECT_GE(b->t_us, a->t_us);
    auto c = r.next();
    ASSERT_TRUE(c);
    EXPECT_EQ(c->kind, CaptureKind::tx);
    EXPECT_TRUE(c->payload.empty());
    EXPECT_FALSE(r.next());
    EXPECT_FALSE(r.truncated_at());
    fs::remove(path);
}

TEST(Capture, ACutLastRecordIsSkippedAndItsOffsetReported) {
    const std::string path = temp_file("cut.cap");
    std::uint64_t second_offset = 0;
    {
        CaptureWriter w(path, {});
        const std::uint8_t bytes[10] = {};
        w.write(CaptureKind::rx, bytes, sizeof bytes);
        second_offset = fs::file_size(path);
        w.write(CaptureKind::rx, bytes, sizeof bytes);
    }
    fs::resize_file(path, fs::file_size(path) - 3);
    CaptureReader r(path);
    ASSERT_TRUE(r.next());
    EXPECT_FALSE(r.next());
    ASSERT_TRUE(r.truncated_at());
    EXPECT_EQ(*r.truncated_at(), second_offset);
    fs::remove(path);
}

TEST(Capture, NotACaptureIsADataErrorAndATailOfNoRecordIsDamage) {
    const std::string path = temp_file("bad.cap");
    std::ofstream(path) << "# driftlab-log: 1\n";
    EXPECT_THROW(CaptureReader{path}, DataError);
    std::ifstream log_head(path);
    EXPECT_FALSE(starts_as_capture(log_head));
    std::ofstream(path, std::ios::binary) << "driftlab-capture: 1\n\nX00000000000000";
    CaptureReader r(path);
    EXPECT_FALSE(r.next());
    EXPECT_FALSE(r.truncated_at());
    ASSERT_EQ(r.damaged().size(), 1u);
    EXPECT_EQ(r.damaged()[0].offset, 21u);
    EXPECT_EQ(r.damaged()[0].bytes, 15u);
    // A later format is named as such, as a log's version is, not as something else.
    std::ofstream(path, std::ios::binary) << "driftlab-capture: 2\n\n";
    std::ifstream later_head(path);
    EXPECT_TRUE(starts_as_capture(later_head));
    try {
        CaptureReader{path};
        ADD_FAILURE() << "format version 2 was read";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find(":1: capture format version '2' is not supported"), std::string::npos)
            << e.what();
    }
    // A damaged header key is the capture's fault, named by its line (it had surfaced as a usage error of the log).
    std::ofstream(path, std::ios::binary) << "driftlab-capture: 1\nport: /dev/ttyUSB0\nbAud: 9600\n\n";
    try {
        CaptureReader{path};
        ADD_FAILURE() << "a key that is no metadata key was accepted";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find(":3: header key 'bAud' is not lower_snake_case"), std::string::npos)
            << e.what();
    }
    fs::remove(path);
}

// Bytes overwritten in the middle of a capture (here the kind, time and length of the third of six records) lose
// that record only: the reader resumes where whole records follow one another again and says where it skipped.
TEST(Capture, ADamagedStretchIsSkippedToTheNextWholeRecords) {
    const std::string path = temp_file("damaged.cap");
    const std::vector<std::uint64_t> offsets = six_records(path);
    {
        std::fstream f(path, std::ios::binary | std::ios::in | std::ios::out);
        f.seekp(static_cast<std::streamoff>(offsets[2]));
        const char junk[13] = {'\x55', '\x01', '\x02', '\x03', '\x04', '\x05', '\x06',
                               '\x07', '\x08', '\x09', '\x0a', '\x0b', '\x0c'};
        f.write(junk, sizeof junk);
    }
    CaptureReader r(path);
    std::vector<std::uint64_t> read;
    while (auto rec = r.next()) {
        read.push_back(rec->offset);
        EXPECT_EQ(rec->payload.size(), 7u);
        EXPECT_EQ(rec->payload[1],
                  static_cast<std::uint8_t>(std::find(offsets.begin(), offsets.end(), rec->offset) - offsets.begin()));
    }
    EXPECT_EQ(read, (std::vector<std::uint64_t>{offsets[0], offsets[1], offsets[3], offsets[4], offsets[5]}));
    ASSERT_EQ(r.damaged().size(), 1u);
    EXPECT_EQ(r.damaged()[0].offset, offsets[2]);
    EXPECT_EQ(r.damaged()[0].bytes, offsets[3] - offsets[2]);
    EXPECT_FALSE(r.truncated_at());
    fs::remove(path);
}

// A stream-mode recorder writes nothing while the board is silent: records more than a day after the last are read
// where whole records follow them (here the last three, 25 h later); they had been dropped as a killed recorder's tail.
TEST(Capture, RecordsAfterASilenceOfMoreThanADayAreRead) {
    const std::string path = temp_file("silent.cap");
    const std::vector<std::uint64_t> offsets = six_records(path);
    {
        std::fstream f(path, std::ios::binary | std::ios::in | std::ios::out);
        for (std::size_t k = 3; k < 6; ++k) {
            f.seekg(static_cast<std::streamoff>(offsets[k] + 1));  // after the kind byte: t_us, u64 little-endian
            std::uint8_t b[8];
            f.read(reinterpret_cast<char*>(b), 8);
            std::uint64_t t = 0;
            for (int i = 7; i >= 0; --i) t = (t << 8) | b[i];
            t += 25ULL * 3600 * 1'000'000;
            for (int i = 0; i < 8; ++i) b[i] = static_cast<std::uint8_t>(t >> (8 * i));
            f.seekp(static_cast<std::streamoff>(offsets[k] + 1));
            f.write(reinterpret_cast<const char*>(b), 8);
        }
    }
    CaptureReader r(path);
    const std::vector<std::uint64_t> read = offsets_read(r);
    EXPECT_EQ(read, offsets);
    EXPECT_TRUE(r.damaged().empty());
    EXPECT_FALSE(r.truncated_at());
    fs::remove(path);
}

// A damaged length field (here the third of six records claims 40 bytes, not 7) would swallow the records after it
// and hand them to the decoder as its payload: it is damage, and the records inside it are read.
TEST(Capture, ADamagedLengthDoesNotSwallowTheRecordsAfterIt) {
    const std::string path = temp_file("badlen.cap");
    const std::vector<std::uint64_t> offsets = six_records(path);
    {
        std::fstream f(path, std::ios::binary | std::ios::in | std::ios::out);
        f.seekp(static_cast<std::streamoff>(offsets[2] + 9));  // kind u8, t_us u64, then len u32
        const char len[4] = {40, 0, 0, 0};
        f.write(len, sizeof len);
    }
    CaptureReader r(path);
    const std::vector<std::uint64_t> read = offsets_read(r);
    EXPECT_EQ(read, (std::vector<std::uint64_t>{offsets[0], offsets[1], offsets[3], offsets[4], offsets[5]}));
    ASSERT_EQ(r.damaged().size(), 1u);
    EXPECT_EQ(r.damaged()[0].offset, offsets[2]);
    EXPECT_EQ(r.damaged()[0].bytes, offsets[3] - offsets[2]);
    fs::remove(path);
}

// One flipped bit in a record's time (+4.2 s, well inside a day): the next record does not follow it but follows
// the one before. The record is read at the previous record's time, and every later record is read too (its time
// had become the reference they all fell behind, and the rest of the file was reported as cut by a kill).
TEST(Capture, ARecordWhoseTimeJumpedAheadIsReadAtThePreviousTime) {
    const std::string path = temp_file("badtime.cap");
    const std::vector<std::uint64_t> offsets = six_records(path);
    {
        std::fstream f(path, std::ios::binary | std::ios::in | std::ios::out);
        f.seekg(static_cast<std::streamoff>(offsets[2] + 1 + 2));  // t_us byte 2
        char byte = 0;
        f.read(&byte, 1);
        byte = static_cast<char>(byte ^ 0x40);
        f.seekp(static_cast<std::streamoff>(offsets[2] + 1 + 2));
        f.write(&byte, 1);
    }
    CaptureReader r(path);
    std::vector<CaptureRecord> records;
    while (auto rec = r.next()) records.push_back(*rec);
    ASSERT_EQ(records.size(), 6u);
    EXPECT_EQ(records[2].offset, offsets[2]);
    EXPECT_EQ(records[2].t_us, records[1].t_us);
    EXPECT_LE(records[5].t_us - records[0].t_us, 1'000'000u);
    EXPECT_EQ(r.retimed(), (std::vector<std::uint64_t>{offsets[2]}));
    EXPECT_TRUE(r.damaged().empty());
    EXPECT_FALSE(r.truncated_at().has_value());
    fs::remove(path);
}
