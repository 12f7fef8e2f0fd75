// The views of a host-in-the-loop run (`driftlab hil`): the summary a terminal shows, and its JSON (docs/sim.md
// §Host-in-the-loop): what was simulated, what the link did to the frames and what reached the log.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "sim/hil/hil.hpp"

namespace driftlab::host::view {

struct HilRun {
    std::string log_path;  ///< "-": standard output
    std::string preset, model_name;
    std::string effects;  ///< the model's effects by name, comma-separated; "" for none
    std::uint64_t seed = 0;
    double duration_s = 0.0;  ///< asked for
    double wall_s = 0.0;
    sim::HilSummary summary;

    double real_time_factor() const { return wall_s > 0.0 ? summary.simulated_s / wall_s : 0.0; }
};

/// Every count that takes an output away from the log, so that outputs and rows add up from the text alone.
void print_hil_summary(std::ostream& out, const HilRun& run);

/// The run as JSON: log, preset, model, seed, durations, frame and row counts, link and firmware counters.
nlohmann::json hil_json(const HilRun& run);

}  // namespace driftlab::host::view
