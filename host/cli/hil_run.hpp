// What `driftlab hil` is asked to run (cmd_hil.cpp): its options, checked against each other, the run they make
// (the model with the preset's and the command line's CONFIG over its own, the duration, the target), and running it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "host/io/capture.hpp"
#include "sim/hil/hil.hpp"
#ifdef DRIFTLAB_HAVE_SIM_AVR
#include "sim/avr/avr_hil.hpp"
#endif

namespace driftlab::host::cli {

struct HilCliOptions {
    std::string preset = "fig3";
    std::optional<double> duration_s;
    std::optional<double> period_s;
    std::optional<int> window;
    std::optional<int> conversions;
    std::optional<int> order;
    std::optional<double> warm_s;
    std::string model_file;
    std::uint64_t seed = 1;
    bool raw = false;
    bool stream = false;
    std::string output;
    bool json = false;
    std::string target = "native";        // native | avr (the real ELF in simavr, docs/avr-in-the-loop.md)
    std::string elf;                      // AVR firmware; default: the one this build made
    int gdb_port = 0;                     // > 0: simavr's gdb stub on this port, CPU stopped until avr-gdb continues
    bool cycles = false;                  // AVR: also print the firmware's cycle budget at this configuration
    bool pty = false;                     // serve the board on a pseudo-terminal instead of running a host
    std::optional<double> speed;          // --pty: virtual seconds per wall second (1 when not given)
    std::string pty_link;                 // --pty: stable symlink to the pseudo-terminal
    std::string trajectory;               // the robot the unit rides: a built-in name or a profile file; empty: at rest
    std::optional<double> rest_before_s;  // at rest this long before the trajectory starts [s of board time]
    std::string plot_dir;                 // --trajectory: draw the truth's and the gyro's yaw rate here
    std::string cal_file;                 // CAL.json the board applies: uploaded (CAL_SET) or, with --pty, stored
    std::string key_file;                 // the board's command key (keygen), in its EEPROM; the host signs with it
};

/// The run `o` asks for. Throws UsageError for options that belong to another way of running, a configuration the
/// firmware or the link would refuse because of the command line, and a duration shorter than one output; ConfigError
/// where the model file's own configuration is at fault.
sim::HilOptions build_options(const HilCliOptions& o);

/// The run's own metadata beside the board's: the effects the model file switches on, by name (their parameters are
/// in the file), and the trajectory, so that a log says what was simulated without the file beside it.
io::CaptureHeader run_metadata(const HilCliOptions& o, const sim::HilOptions& h, const std::string& effects);

/// The log's instants and gyro values, which the truth and the plot of a run in motion are drawn at.
struct MotionRows {
    std::vector<double> t_s, gyro_counts;
};

/// Writes the ground truth of `h`'s trajectory beside the log at `log_path`, a row at each of its rows, whole or not
/// at all (sim/motion/truth_table.hpp); with --plot, the truth's yaw rate beside the gyro's reading of it (its
/// counts less the model's eq. 1, over the front end's counts per deg/s).
void write_motion_outputs(const HilCliOptions& o, const sim::HilOptions& h, const std::string& log_path,
                          const MotionRows& rows);

/// The effects `h`'s model switches on, by name, comma-separated ("" for none).
std::string effect_names(const sim::HilOptions& h);

/// Runs `h` (made from `o` by build_options()) into the canonical log at `path`, and in motion its ground truth
/// beside it (write_motion_outputs()): what `hil` writes, and `nav-eval` for each of its runs.
sim::HilSummary write_hil_log(const HilCliOptions& o, sim::HilOptions& h, const std::string& path);

/// The run; an emulated AVR that fails (the firmware crashed or stopped converting) is a device's failure
/// (DeviceError).
sim::HilSummary run_board(const sim::HilOptions& h, const sim::RecordSink& on_record);

#ifdef DRIFTLAB_HAVE_SIM_AVR
/// --elf, or the firmware this build made.
std::string firmware_elf(const HilCliOptions& o);

/// What --cycles measures: every instruction profiled, so a short run of its own rather than the run the log came
/// from.
inline const std::string kCycleRun = "5 s of streaming after 0.5 s (no POLL, so no receive interrupts)";

/// The firmware's cycle budget at `h`'s configuration, over kCycleRun.
sim::avr::CycleBudget cycle_budget(const HilCliOptions& o, const sim::HilOptions& h);
#endif

}  // namespace driftlab::host::cli
