// `--shard K/N -o PART`, as gap-eval and nav-eval take it (docs/cluster.md).
#pragma once

#include <cstddef>
#include <string>
#include <utility>

#include <CLI/CLI.hpp>

namespace driftlab::host::cli {

/// Adds `--shard K/N` (0 <= K < N <= 100000, as SLURM_ARRAY_TASK_ID and JOB_COMPLETION_INDEX count) and `-o,--output
/// PART`, each needing the other; `items` says what the shard's share is of. Returns the output option, for the
/// command's own exclusions.
CLI::Option* add_shard_options(CLI::App* cmd, std::pair<std::size_t, std::size_t>& shard, std::string& part,
                               const std::string& items);

}  // namespace driftlab::host::cli
