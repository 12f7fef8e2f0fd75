// What a fleet prints; see fleet_output.hpp.
#include "host/cli/fleet_output.hpp"

#include <iostream>

#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/view/fleet_view.hpp"
#include "host/view/json_out.hpp"

namespace driftlab::host::cli {

void print_fleet(const std::vector<fleet::BoardEntry>& boards, bool json, const std::string& plot_dir,
                 const std::string& report_dir) {
    const view::FleetView v{&boards, fleet::summarise(boards)};
    if (json)
        view::write_json(std::cout, view::fleet_json(v));
    else
        view::print_fleet_text(std::cout, v);
    if (!plot_dir.empty()) view::write_fleet_plots(v, plot_dir);
    if (!report_dir.empty()) view::write_fleet_report(v, report_dir);
    std::vector<const fleet::BoardEntry*> failed;
    for (const fleet::BoardEntry& b : boards)
        if (!b.result) failed.push_back(&b);
    if (failed.empty()) return;
    // Each reason is in the output above; the exit names the logs, so that a script sees the batch was not whole.
    std::string others;
    for (std::size_t i = 1; i < failed.size(); ++i) others += (i > 1 ? ", " : "") + failed[i]->log;
    throw DataError(failed.front()->log, 0,
                    "not analysed" + (others.empty() ? std::string() : " (nor " + others + ")") + "; the other " +
                        counted(boards.size() - failed.size(), "board") + " are reported");
}

}  // namespace driftlab::host::cli
