// 64-bit FNV-1a: a stable fingerprint of bytes (a build's executable, a log a result was computed from), the same on
// every machine and run, which std::hash is not required to be. Not for adversaries.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace driftlab::host {

class Fnv1a {
public:
    void add(std::string_view bytes) {
        for (const char c : bytes) {
            hash_ ^= static_cast<unsigned char>(c);
            hash_ *= 0x100000001b3ull;
        }
    }
    /// Sixteen hexadecimal digits.
    std::string hex() const {
        char text[17];
        std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
        return text;
    }

private:
    std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

/// The FNV-1a of a file's bytes; "" when it cannot be read.
std::string file_fingerprint(const std::string& path);

}  // namespace driftlab::host
