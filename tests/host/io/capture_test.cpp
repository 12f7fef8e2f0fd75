// Capture file: records round-trip, a cut last record is reported with its offset, bad input names its place.
#include "host/io/capture.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "host/util/error.hpp"

namespace fs = std::filesystem;
using namespace driftlab::host;
using namespace driftlab::host::io;

namespace {

std::string temp_file(const std::string& name) {
    return (fs::temp_directory_path() / ("driftlab_cap_" + std::to_string(::getpid()) + "_" + name)).string();
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

TEST(Capture, NotACaptureAndUnknownRecordKindAreDataErrors) {
    const std::string path = temp_file("bad.cap");
    std::ofstream(path) << "# driftlab-log: 1\n";
    EXPECT_THROW(CaptureReader{path}, DataError);
    std::ofstream(path, std::ios::binary) << "driftlab-capture: 1\n\nX00000000000000";
    CaptureReader r(path);
    try {
        static_cast<void>(r.next());
        FAIL() << "expected DataError";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find("byte offset 21"), std::string::npos) << e.what();
    }
    fs::remove(path);
}
