// --exclude FROM:TO, which gap, fit, whiteness, report and allan share: stretches of rows a user leaves out.
#include <optional>
#include <string>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/log/log_window.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::cli {
namespace {

// One --exclude value; UsageError unless it is two finite numbers FROM:TO with FROM before TO.
TimeWindow parse_exclude(const std::string& text) {
    const auto refused = [&] {
        return UsageError("--exclude: expected FROM:TO in seconds since power-on (e.g. 600:640), got '" + text + "'");
    };
    const auto number = [&](const std::string& part) {
        const std::optional<double> v = finite_number(part);
        if (!v) throw refused();
        return *v;
    };
    const auto colon = text.find(':');
    if (colon == std::string::npos) throw refused();
    const TimeWindow w{number(text.substr(0, colon)), number(text.substr(colon + 1)), "--exclude"};
    if (!(w.from_s < w.to_s)) throw UsageError("--exclude " + text + ": FROM must be before TO");
    return w;
}

}  // namespace

void add_exclude_option(CLI::App* cmd, std::vector<TimeWindow>& windows, const std::string& what_becomes_of_them) {
    // Parsed as the command line is, so that a mistaken window is refused before a long log is read.
    cmd->add_option_function<std::vector<std::string>>(
        "--exclude",
        [&windows](const std::vector<std::string>& texts) {
            for (const std::string& text : texts) windows.push_back(parse_exclude(text));
        },
        "Leave out the rows from FROM to TO [s since power-on], e.g. 600:640: " + what_becomes_of_them +
            " (repeat for more)");
}

}  // namespace driftlab::host::cli
