// Key files and the EEPROM image of a key: keygen's file is owner-only and reads back; an existing file is not
// written over, a file others may read is refused, as is one that is not 32 hex digits; the Intel HEX of a key record
// is the one written out independently (Python, the record's CRC-16/IBM-3740 by hand); avrdude is asked to write it.
#include "host/io/key_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "firmware/core/key_record.hpp"
#include "host/io/avrdude.hpp"
#include "host/io/intel_hex.hpp"
#include "host/util/error.hpp"
#include "tests/support/temp_dir.hpp"

namespace driftlab::host::io {
namespace {

TEST(KeyFile, AKeyIsWrittenOwnerOnlyReadBackAndNeverWrittenOver) {
    test_support::TempDir dir("keyfile");
    const std::string path = dir.file("board.key");
    const CommandKey key = new_key();
    write_key_file(path, key);
    struct stat st {};
    ASSERT_EQ(::stat(path.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0600u);
    EXPECT_EQ(std::filesystem::file_size(path), 33u);
    EXPECT_EQ(read_key_file(path), key);
    EXPECT_THROW(write_key_file(path, new_key()), UsageError);
    EXPECT_EQ(read_key_file(path), key);
    // Its EEPROM image for avrdude is as private as the key and starts with the record's first 16 bytes at byte 96.
    const std::string image = write_key_eeprom_image(path);
    ASSERT_EQ(::stat(image.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0600u);
    std::ifstream in(image);
    std::string first;
    std::getline(in, first);
    EXPECT_EQ(first.substr(0, 9), ":10006000");
    EXPECT_NE(new_key(), new_key());  // 2^-128 to fail by chance
}

TEST(KeyFile, AFileOthersMayReadOrThatIsNoKeyIsRefusedNamingIt) {
    test_support::TempDir dir("keybad");
    const std::string open = dir.file("open.key");
    write_key_file(open, new_key());
    ::chmod(open.c_str(), 0644);
    try {
        read_key_file(open);
        FAIL() << "a 0644 key was read";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find(open + ": permissions 0644"), std::string::npos) << e.what();
    }
    const std::string short_key = dir.file("short.key");
    std::ofstream(short_key) << "00112233\n";
    ::chmod(short_key.c_str(), 0600);
    EXPECT_THROW(read_key_file(short_key), DataError);
}

TEST(KeyFile, TheKeyRecordsIntelHexIsTheIndependentlyWrittenOne) {
    std::uint8_t key[16];
    for (std::uint8_t i = 0; i < 16; ++i) key[i] = i;
    std::uint8_t record[fw::kKeyRecordBytes];
    fw::key_record_bytes(key, record);
    EXPECT_EQ(intel_hex(fw::kKeyEepromAddress, std::vector<std::uint8_t>(record, record + sizeof record)),
              ":10006000000102030405060708090A0B0C0D0E0F18\n:02007000373B1C\n:00000001FF\n");
    FlashRequest r;
    r.port = "/dev/ttyACM0";
    r.hex_file = "fw.hex";
    r.eeprom_hex_file = "board.key.eeprom.hex";
    const std::vector<std::string> args = avrdude_arguments(r);
    ASSERT_GE(args.size(), 2u);
    EXPECT_EQ(args[args.size() - 2], "-U");
    EXPECT_EQ(args.back(), "eeprom:w:board.key.eeprom.hex:i");
}

}  // namespace
}  // namespace driftlab::host::io
