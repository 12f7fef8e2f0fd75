// The views of `driftlab fleet` (docs/fleet.md): per board its channels' eq. 1 parameters and noise terms and its gap
// verdict; the batch's medians and spreads; the boards that stand out, with why; the logs that could not be read.
// Text, JSON, a markdown report, and per channel a plot of every board's robust z-score by parameter.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "host/fleet/batch.hpp"

namespace driftlab::host::view {

/// What every view shows: the boards, in the fleet's order, and their batch.
struct FleetView {
    const std::vector<fleet::BoardEntry>* boards = nullptr;
    fleet::Batch batch;
};

void print_fleet_text(std::ostream& out, const FleetView& v);
/// A board's parameter in a table: "value ± error" with `plus_minus` between them, `unknown` where the log does not
/// determine it (text and report alike, each in its own symbols).
std::string estimate_cell(const fleet::Estimate& e, const std::string& plus_minus, const std::string& unknown);
/// The cells of channel `channel`'s row of board result `r`, text and report alike: its six parameters
/// (estimate_cell(): what the analysis determined before it failed, if it did, as the batch counts it; the failure is
/// a standout), then the gap verdict ("failed" where the diagnosis failed, `unknown` where it was not run).
std::vector<std::string> channel_cells(const fleet::BoardResult& r, std::size_t channel, const std::string& plus_minus,
                                       const std::string& unknown);
/// A batch's spread in a table: for a log-scale parameter its factor after `factor_sign` ("x/", "×/"), else the spread.
std::string spread_cell(const fleet::Distribution& d, const std::string& factor_sign);
/// "none 19; unexplained 1 (b12.csv). The diagnosis names an effect on a clean log about 5 % of the time: 1 of 20
/// boards by chance".
std::string verdict_summary(const FleetView& v);
nlohmann::json fleet_json(const FleetView& v);
/// fleet_<channel>.png/svg for each channel with a judged parameter; returns the image files' stems' paths.
std::vector<std::string> write_fleet_plots(const FleetView& v, const std::string& dir);
/// fleet.md with the figures beside it in `dir`.
void write_fleet_report(const FleetView& v, const std::string& dir);

}  // namespace driftlab::host::view
