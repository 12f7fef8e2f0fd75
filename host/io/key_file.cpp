// Key files (key_file.hpp).
#include "host/io/key_file.hpp"

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "firmware/core/key_record.hpp"
#include "host/io/intel_hex.hpp"
#include "host/util/error.hpp"
#include "host/util/input_file.hpp"

namespace driftlab::host::io {
namespace {

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

}  // namespace

CommandKey new_key() {
    CommandKey key{};
    if (getrandom(key.data(), key.size(), 0) != static_cast<ssize_t>(key.size()))
        throw DeviceError("getrandom", std::string("no random bytes: ") + std::strerror(errno));
    return key;
}

void write_key_file(const std::string& path, const CommandKey& key) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0 && errno == EEXIST)
        throw UsageError(path + ": a file is already there; a key is not written over (remove it first)");
    if (fd < 0) throw DeviceError(path, std::string("cannot create the key file: ") + std::strerror(errno));
    char text[2 * 16 + 2];
    for (std::size_t i = 0; i < key.size(); ++i) std::snprintf(text + 2 * i, 3, "%02x", key[i]);
    text[32] = '\n';
    const bool written = ::write(fd, text, 33) == 33 && ::fsync(fd) == 0;
    ::close(fd);
    if (!written) {
        std::filesystem::remove(path);
        throw DeviceError(path, "cannot write the key file");
    }
}

CommandKey read_key_file(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) throw DataError(path, 0, std::string("cannot read: ") + std::strerror(errno));
    if ((st.st_mode & 077) != 0) {
        char mode[8];
        std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 0777));
        throw DataError(path, 0,
                        std::string("permissions ") + mode + " let others read or change the key: chmod 600 " + path);
    }
    const std::string text = read_small_file(path, 64);
    const std::string digits = !text.empty() && text.back() == '\n' ? text.substr(0, text.size() - 1) : text;
    CommandKey key{};
    bool ok = digits.size() == 32;
    for (std::size_t i = 0; ok && i < key.size(); ++i) {
        const int hi = hex_digit(digits[2 * i]);
        const int lo = hex_digit(digits[2 * i + 1]);
        ok = hi >= 0 && lo >= 0;
        key[i] = static_cast<std::uint8_t>(ok ? hi * 16 + lo : 0);
    }
    if (!ok) throw DataError(path, 1, "not a key: 32 hex digits expected (driftlab keygen makes one)");
    return key;
}

std::string write_key_eeprom_image(const std::string& key_path) {
    const CommandKey key = read_key_file(key_path);
    std::uint8_t raw[16];
    std::copy(key.begin(), key.end(), raw);
    std::uint8_t record[fw::kKeyRecordBytes];
    fw::key_record_bytes(raw, record);
    const std::string path = key_path + ".eeprom.hex";
    const std::string text =
        intel_hex(fw::kKeyEepromAddress, std::vector<std::uint8_t>(record, record + sizeof record));
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    const bool written = fd >= 0 && ::fchmod(fd, 0600) == 0 &&
                         ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
    if (fd >= 0) ::close(fd);
    if (!written) throw DeviceError(path, "cannot write the key's EEPROM image");
    return path;
}

}  // namespace driftlab::host::io
