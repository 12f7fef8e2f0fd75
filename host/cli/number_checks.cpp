// Option checks for numbers; see commands.hpp.
#include <cmath>
#include <string>

#include "host/cli/commands.hpp"

namespace driftlab::host::cli {
namespace {

CLI::Validator number_check(const char* name, bool zero_allowed) {
    return CLI::Validator(
        [zero_allowed](std::string& text) -> std::string {
            std::size_t used = 0;
            double v = NAN;
            try {
                v = std::stod(text, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            const bool ok = used == text.size() && std::isfinite(v) && (zero_allowed ? v >= 0.0 : v > 0.0);
            return ok ? std::string() : std::string("expected a number ") + (zero_allowed ? ">= 0" : "> 0") + ", got '" + text + "'";
        },
        name);
}

}  // namespace

const CLI::Validator& positive_number() {
    static const CLI::Validator check = number_check("POSITIVE", false);
    return check;
}

const CLI::Validator& non_negative_number() {
    static const CLI::Validator check = number_check("NONNEGATIVE", true);
    return check;
}

}  // namespace driftlab::host::cli
