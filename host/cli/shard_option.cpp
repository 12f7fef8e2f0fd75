// `--shard K/N -o PART`; see shard_option.hpp.
#include "host/cli/shard_option.hpp"

#include "host/cli/commands.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::cli {
namespace {

std::pair<std::size_t, std::size_t> parse_shard(const std::string& s) {
    const auto refused = [&] { return UsageError("--shard: expected K/N with 0 <= K < N <= 100000, got '" + s + "'"); };
    const auto slash = s.find('/');
    const auto number = [&](const std::string& text) {
        if (text.empty() || text.size() > 6 || text.find_first_not_of("0123456789") != std::string::npos)
            throw refused();
        return static_cast<std::size_t>(std::stoull(text));
    };
    if (slash == std::string::npos) throw refused();
    const std::size_t k = number(s.substr(0, slash)), n = number(s.substr(slash + 1));
    if (n == 0 || n > 100000 || k >= n) throw refused();
    return {k, n};
}

}  // namespace

CLI::Option* add_shard_options(CLI::App* cmd, std::pair<std::size_t, std::size_t>& shard, std::string& part,
                               const std::string& items) {
    CLI::Option* s =
        cmd->add_option_function<std::string>(
               "--shard", [&shard](const std::string& text) { shard = parse_shard(text); },
               "Run shard K of N (K = 0..N-1, as SLURM_ARRAY_TASK_ID counts): its share of the campaign's " + items +
                   " (docs/cluster.md says which), each as the one-process run makes it; with -o, its "
                   "part for `driftlab merge`")
            ->type_name("K/N");
    CLI::Option* o =
        cmd->add_option("-o,--output", part, "The shard's part file (written whole: a temporary file, then a rename)")
            ->check(non_empty_path());
    s->needs(o);
    o->needs(s);
    return o;
}

}  // namespace driftlab::host::cli
