// Round-trip number formatting; see format_number.hpp.
#include "host/util/format_number.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string_view>

namespace driftlab::host {

namespace {

// printf keeps the sign of a negative value that rounds to zero ("-0.0", "-0 %"), which reads as a change where the
// text shows none.
std::string without_negative_zero(const char* text) {
    if (text[0] == '-' && std::string_view(text + 1).find_first_not_of("0.") == std::string_view::npos) return text + 1;
    return text;
}

// `value` fixed-point with its last digit at 10^last, where that reads plainly: a last digit from 1e-12 up and a
// magnitude below 1e9 (a wider value is clearer with an exponent). A last digit left of the point rounds there too:
// %.0f alone wrote every digit, "3 ± 120" for 0 ± 120.
std::optional<std::string> plain_to_digit(double value, int last) {
    if (last < -12 || !(std::fabs(value) < 1e9)) return std::nullopt;
    if (last > 0) {
        const double unit = std::pow(10.0, last);
        value = std::round(value / unit) * unit;
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", std::max(0, -last), value);
    return without_negative_zero(buf);
}

}  // namespace

void append_double(std::string& out, double value) {
    // The shortest text alone is scientific wherever that is shorter: a tick count of 5000000 read "5e+06" beside
    // 5025000 on the next row, and 0.0001 read "1e-04". Fixed-point is kept where a reader expects it.
    const double magnitude = std::fabs(value);
    const bool fixed = magnitude >= 1e-4 && magnitude < 1e15;
    char buf[48];
    const auto result = fixed ? std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed)
                              : std::to_chars(buf, buf + sizeof buf, value);
    out.append(buf, result.ptr);
}

std::string format_double(double value) {
    std::string s;
    append_double(s, value);
    return s;
}

std::string to_precision_of(double value, double uncertainty) {
    char buf[64];
    if (!std::isfinite(value) || !std::isfinite(uncertainty) || !(uncertainty > 0.0)) {
        std::snprintf(buf, sizeof buf, "%.6g", value);
        return buf;
    }
    const int last = static_cast<int>(std::floor(std::log10(uncertainty))) - 1;  // power of ten of the last digit
    if (uncertainty < 1e9)
        if (const auto plain = plain_to_digit(value, last)) return *plain;
    const int lead = value != 0.0 ? static_cast<int>(std::floor(std::log10(std::fabs(value)))) : last + 1;
    std::snprintf(buf, sizeof buf, "%.*e", std::clamp(lead - last, 0, 16), value);
    return buf;
}

std::string value_with_error(double value, double error, const std::string& plus_minus) {
    if (!std::isfinite(error) || error < 0.0) return to_precision_of(value, error);
    return to_precision_of(value, error) + " " + plus_minus + " " + to_precision_of(error, error);
}

std::string significant_plain(double value, int digits) {
    if (value == 0.0) return "0";
    if (!std::isfinite(value) || digits < 1) return significant(value, digits);
    // Rounded by %e first, whose exponent is then the leading digit's (9.9996 at 4 digits leads at 10), and whose
    // digits are the only ones kept (11912.3 at 4 digits is 11910, where %.0f alone would write every digit).
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*e", digits - 1, value);
    const int lead = std::atoi(std::strchr(buf, 'e') + 1);
    const auto plain = plain_to_digit(std::strtod(buf, nullptr), lead - digits + 1);
    if (!plain) return significant(value, digits);
    std::string text = *plain;
    if (text.find('.') != std::string::npos) {
        text.erase(text.find_last_not_of('0') + 1);
        if (text.back() == '.') text.pop_back();
    }
    return text;
}

std::string significant(double value, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, value);
    return buf;
}

std::string fixed_point(double value, int decimals) {
    char buf[400];  // %f of 1e308 has 309 digits before the point
    std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
    return without_negative_zero(buf);
}

std::string counted(std::size_t n, const std::string& noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

}  // namespace driftlab::host
