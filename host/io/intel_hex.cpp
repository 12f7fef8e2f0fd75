// Intel HEX records (intel_hex.hpp).
#include "host/io/intel_hex.hpp"

#include <algorithm>
#include <cstdio>

namespace driftlab::host::io {

std::string intel_hex(std::uint16_t address, const std::vector<std::uint8_t>& bytes) {
    std::string out;
    char field[16];
    for (std::size_t at = 0; at < bytes.size(); at += 16) {
        const std::size_t n = std::min<std::size_t>(16, bytes.size() - at);
        const unsigned a = address + static_cast<unsigned>(at);
        unsigned sum = static_cast<unsigned>(n) + (a >> 8) + (a & 0xFF);
        std::snprintf(field, sizeof field, ":%02X%04X00", static_cast<unsigned>(n), a & 0xFFFF);
        out += field;
        for (std::size_t i = 0; i < n; ++i) {
            std::snprintf(field, sizeof field, "%02X", bytes[at + i]);
            out += field;
            sum += bytes[at + i];
        }
        std::snprintf(field, sizeof field, "%02X\n", (0x100 - (sum & 0xFF)) & 0xFF);
        out += field;
    }
    return out + ":00000001FF\n";
}

}  // namespace driftlab::host::io
