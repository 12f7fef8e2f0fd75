// Round-trip number formatting; see format_number.hpp.
#include "host/util/format_number.hpp"

#include <charconv>

namespace driftlab::host {

void append_double(std::string& out, double value) {
    char buf[32];
    const auto result = std::to_chars(buf, buf + sizeof buf, value);
    out.append(buf, result.ptr);
}

std::string format_double(double value) {
    std::string s;
    append_double(s, value);
    return s;
}

}  // namespace driftlab::host
