// --from/--to, the time range the analysing commands keep; checked as the command line is read.
#include <string>

#include "host/cli/commands.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::cli {

void add_time_range_options(CLI::App* cmd, double& t_min_s, double& t_max_s) {
    // --from/--to first, as the notes name them; --t-min/--t-max, fit's first spelling, work in every command that
    // keeps a range (a refusal names both spellings: main.cpp).
    cmd->add_option("--from,--t-min", t_min_s,
                    "Analyse only rows from this time on [s: a log's t_s since power-on, a "
                    "table's time]: leave out a disturbed start")
        ->check(finite_value());
    cmd->add_option("--to,--t-max", t_max_s,
                    "Analyse only rows up to this time [s, as --from]: leave out a disturbed end")
        ->check(finite_value());
    // Once the whole command line is read, as either option may come first; before a long log is read.
    cmd->parse_complete_callback([&t_min_s, &t_max_s] {
        if (!(t_min_s < t_max_s)) throw UsageError("--from must be before --to");
    });
}

}  // namespace driftlab::host::cli
