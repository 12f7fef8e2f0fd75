// Option checks for numbers and paths; see commands.hpp. A check's description is what --help shows after the
// option's type (help_formatter.cpp): its range in the words of its refusal ("FLOAT > 0"), or none where the type
// says enough (a finite FLOAT, a TEXT path, a UINT seed).
#include <cmath>
#include <limits>
#include <string>

#include "driftlab/proto/messages.hpp"
#include "host/cli/commands.hpp"
#include "host/io/serial_port.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"

namespace driftlab::host::cli {
namespace {

CLI::Validator number_check(bool zero_allowed) {
    const std::string range = zero_allowed ? ">= 0" : "> 0";
    return CLI::Validator(
        [zero_allowed, range](std::string& text) -> std::string {
            const std::optional<double> v = finite_number(text);
            const bool ok = v && (zero_allowed ? *v >= 0.0 : *v > 0.0);
            return ok ? std::string() : "expected a number " + range + ", got '" + text + "'";
        },
        range);
}

}  // namespace

std::uint16_t output_period_ms(double period_s, const std::string& option) {
    const double ms = period_s * 1000.0;
    if (!(ms >= proto::kOutputPeriodMinMs && ms <= proto::kOutputPeriodMaxMs) || std::abs(ms - std::round(ms)) > 1e-6) {
        throw UsageError(option + ": expected a whole number of milliseconds in [0.01, 60] s, got " +
                         significant(period_s, 6));
    }
    return static_cast<std::uint16_t>(std::lround(ms));
}

std::optional<double> finite_number(const std::string& text) {
    std::size_t used = 0;
    double v = NAN;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        return std::nullopt;
    }
    if (used != text.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

const CLI::Validator& positive_number() {
    static const CLI::Validator check = number_check(false);
    return check;
}

const CLI::Validator& non_negative_number() {
    static const CLI::Validator check = number_check(true);
    return check;
}

const CLI::Validator& finite_value() {
    static const CLI::Validator check(
        [](std::string& text) -> std::string {
            return finite_number(text) ? std::string() : "expected a finite number, got '" + text + "'";
        },
        "");
    return check;
}

CLI::Validator number_in(double low, double high, Bound low_bound) {
    const bool open = low_bound == Bound::open;
    const std::string range = std::string(open ? "(" : "[") + significant(low, 6) + ", " + significant(high, 6) + "]";
    return CLI::Validator(
        [low, high, open, range](std::string& text) -> std::string {
            // CLI::Range had let "nan" through: it compares false with both ends.
            const std::optional<double> v = finite_number(text);
            const bool ok = v && (open ? *v > low : *v >= low) && *v <= high;
            return ok ? std::string() : "expected a number in " + range + ", got '" + text + "'";
        },
        "in " + range);
}

CLI::Validator whole_number_in(long long low, long long high) {
    const std::string range = "[" + std::to_string(low) + ", " + std::to_string(high) + "]";
    return CLI::Validator(
        [low, high, range](std::string& text) -> std::string {
            std::size_t used = 0;
            long long v = 0;
            try {
                v = std::stoll(text, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            const bool ok = used > 0 && used == text.size() && v >= low && v <= high;
            return ok ? std::string() : "expected a whole number in " + range + ", got '" + text + "'";
        },
        "in " + range);
}

const CLI::Validator& baud_rate() {
    static const CLI::Validator check(
        [whole = whole_number_in(1, std::numeric_limits<int>::max())](std::string& text) -> std::string {
            const bool ok = whole(text).empty() && io::is_supported_baud(std::stoi(text));
            return ok ? std::string()
                      : "expected a standard rate [bit/s] (e.g. 9600, 57600, 115200), got '" + text + "'";
        },
        "");
    return check;
}

CLI::Validator non_empty(const std::string& what) {
    return CLI::Validator(
        [what](std::string& text) { return text.empty() ? "expected " + what + ", got ''" : std::string(); }, "");
}

const CLI::Validator& non_empty_path() {
    static const CLI::Validator check = non_empty("a path");
    return check;
}

const CLI::Validator& seed_number() {
    static const CLI::Validator check(
        [](std::string& text) -> std::string {
            // Digits only: the unsigned parse would take "-5" as 2^64 - 5 and clamp 2^64 and beyond to 2^64 - 1.
            const bool digits =
                !text.empty() && text.size() <= 20 && text.find_first_not_of("0123456789") == std::string::npos;
            if (digits && (text.size() < 20 || text <= "18446744073709551615")) return {};
            return "expected a whole number from 0 to 18446744073709551615, got '" + text + "'";
        },
        "");
    return check;
}

}  // namespace driftlab::host::cli
