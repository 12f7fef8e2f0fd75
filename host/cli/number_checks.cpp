// Option checks for numbers and paths; see commands.hpp.
#include <cmath>
#include <string>

#include "driftlab/proto/messages.hpp"
#include "host/cli/commands.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"

namespace driftlab::host::cli {
namespace {

CLI::Validator number_check(const char* name, bool zero_allowed) {
    return CLI::Validator(
        [zero_allowed](std::string& text) -> std::string {
            const std::optional<double> v = finite_number(text);
            const bool ok = v && (zero_allowed ? *v >= 0.0 : *v > 0.0);
            return ok ? std::string() : std::string("expected a number ") + (zero_allowed ? ">= 0" : "> 0") + ", got '" + text + "'";
        },
        name);
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
    static const CLI::Validator check = number_check("POSITIVE", false);
    return check;
}

const CLI::Validator& non_negative_number() {
    static const CLI::Validator check = number_check("NONNEGATIVE", true);
    return check;
}

const CLI::Validator& finite_value() {
    static const CLI::Validator check(
        [](std::string& text) -> std::string {
            return finite_number(text) ? std::string() : "expected a finite number, got '" + text + "'";
        },
        "NUMBER");
    return check;
}

const CLI::Validator& non_empty_path() {
    static const CLI::Validator check(
        [](std::string& text) -> std::string { return text.empty() ? "expected a path, got ''" : std::string(); }, "PATH");
    return check;
}

const CLI::Validator& seed_number() {
    static const CLI::Validator check(
        [](std::string& text) -> std::string {
            // Digits only: the unsigned parse would take "-5" as 2^64 - 5 and clamp 2^64 and beyond to 2^64 - 1.
            const bool digits = !text.empty() && text.size() <= 20 &&
                                text.find_first_not_of("0123456789") == std::string::npos;
            if (digits && (text.size() < 20 || text <= "18446744073709551615")) return {};
            return "expected a whole number from 0 to 18446744073709551615, got '" + text + "'";
        },
        "SEED");
    return check;
}

}  // namespace driftlab::host::cli
