// What `driftlab gap` reads (cmd_gap.cpp): a canonical log as it is, or a plain recording through its column
// mappings, with the unit the simulator stands in for and the rows --from/--to, --exclude and --exclude-saturated
// keep.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "driftlab/channels.hpp"
#include "host/log/log_data.hpp"
#include "host/log/log_window.hpp"
#include "host/log/truth_file.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::host::cli {

struct GapInput {
    std::string path;
    std::string model_path;
    std::vector<std::string> channels;
    std::vector<std::string> mappings;  ///< plain recordings: CHANNEL=COLUMN:LSB
    double tau0_s = 0.0;                ///< plain recordings: the raw sample period
    std::size_t block = 1;              ///< plain recordings: samples averaged per output
    double from_s = -INFINITY;          ///< rows kept: from_s <= t_s <= to_s
    double to_s = INFINITY;
    std::vector<TimeWindow> excluded;  ///< --exclude: stretches left out
    double saturated_margin_s = -1.0;  ///< --exclude-saturated: seconds either side of each saturated stretch; < 0: off
    bool drop_cut_line = false;        ///< canonical logs: a cut last line is dropped (and noted), not refused
    std::string truth_path;            ///< --truth: the ground truth of a canonical log in motion
    bool motion_without_truth = false;  ///< a log in motion is read without its truth (nav: the motion is the point)

    bool windowed() const { return from_s != -INFINITY || to_s != INFINITY; }
};

struct LoadedRecording {
    LogData log;
    sim::SimModel unit;
    std::vector<std::string> notes;  ///< what --from/--to kept (--exclude's windows are the result's left_out)
    std::optional<TruthFile> truth;  ///< --truth, its rows matched to the log's (match_truth_rows())
};

/// --channel: the channels named (none named: all false, which selects every one).
std::array<bool, kChannelCount> channels_named(const GapInput& input);

/// A canonical log as it is, with the unit of --model or the paper's; a plain table through its column mappings
/// (never guessed), with a unit whose codes are the columns' LSBs (set by the whole table); then --from/--to and
/// --exclude; with --truth, the ground truth checked against the rows kept.
LoadedRecording load_recording(const GapInput& input);

/// --as, --tau0 and --block: how a plain recording is read (gap, nav).
void add_plain_recording_options(CLI::App* cmd, GapInput& input);

/// " (rows from X s to Y s, without A s to B s)" where --from/--to, --exclude or --exclude-saturated chose them, else
/// "".
std::string rows_used(const GapInput& input, const LogData& log);

}  // namespace driftlab::host::cli
