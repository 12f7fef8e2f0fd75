// What a fleet prints once every board is analysed, whether one process analysed them (`fleet`) or its shards'
// parts were merged (`merge`): the boards, the batch and the boards that stand out, as text or JSON, plots, a report;
// then, when a log could not be analysed, an error naming it (exit 3), the rest reported.
#pragma once

#include <string>
#include <vector>

#include "host/fleet/batch.hpp"

namespace driftlab::host::cli {

void print_fleet(const std::vector<fleet::BoardEntry>& boards, bool json, const std::string& plot_dir,
                 const std::string& report_dir);

}  // namespace driftlab::host::cli
