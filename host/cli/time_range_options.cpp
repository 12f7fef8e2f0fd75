// --from/--to, the time range the analysing commands keep; checked as the command line is read.
#include <string>

#include "host/cli/commands.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::cli {

void refuse_reversed_time_range(CLI::App* cmd, const double& from_s, const double& to_s) {
    // Once the whole command line is read, as either option may come first; before a long log is read.
    cmd->parse_complete_callback([&from_s, &to_s] {
        if (!(from_s < to_s)) throw UsageError("--from must be before --to");
    });
}

void add_time_range_options(CLI::App* cmd, double& t_min_s, double& t_max_s) {
    // --from/--to first, as gap spells them and as the notes name them; --t-min/--t-max still work (a refusal names
    // both spellings: main.cpp).
    cmd->add_option("--from,--t-min", t_min_s, "Use samples with t_s >= this [s since power-on]")->check(finite_value());
    cmd->add_option("--to,--t-max", t_max_s, "Use samples with t_s <= this [s since power-on]")->check(finite_value());
    refuse_reversed_time_range(cmd, t_min_s, t_max_s);
}

}  // namespace driftlab::host::cli
