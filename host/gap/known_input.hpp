// The known input of a log in motion: what each channel would read of the motion alone, from the ground truth, at
// the board's own conversion instants and through the firmware's own least-squares smoothing, so that `gap --truth`
// can take it out of the log before comparing what is left with a unit at rest. docs/gap.md §A log in motion.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "driftlab/channels.hpp"
#include "host/log/log_data.hpp"
#include "host/log/truth_file.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::host::gap {

/// What the sensors feel of the motion: the yaw rate [deg/s], the forward and lateral specific force [g].
enum class MotionQuantity : std::size_t { yaw_rate = 0, accel_x = 1, accel_y = 2 };
inline constexpr std::size_t kMotionQuantities = 3;

const char* motion_quantity_name(MotionQuantity q);

struct KnownInput {
    /// Per channel and quantity, per log row: the quantity at the channel's conversion instants of the row's
    /// window, smoothed as the firmware smooths the codes [deg/s or g].
    std::array<std::array<std::vector<double>, kMotionQuantities>, kChannelCount> smoothed;
    std::array<double, kChannelCount> counts_per_unit{};  ///< the unit's front end and converter [counts per unit]
    std::string source;             ///< how the truth between rows was had: the trajectory rebuilt, or interpolation
    int newest_channel = 3;         ///< the channel the round robin converts last before the first row
    bool newest_estimated = false;  ///< a polled log: chosen as the one that fits the log best

    /// The known input of channel `c` at each row [counts]: its own quantity (none on accel_z, gravity's 1 g being
    /// the model's at-rest input) in its units through its front end.
    std::vector<double> counts(Channel c) const;
    /// The quantity `q` as channel `c` would read it were `c` sensitive to it [counts].
    std::vector<double> counts(Channel c, MotionQuantity q) const;
};

/// The quantity channel `c` measures, if any.
bool measures(Channel c, MotionQuantity& q);

/// The known input of `log` (rows matched to `truth` by match_truth_rows()) on `unit`. The truth between rows is
/// the trajectory the truth names, rebuilt with the log's seed when it reproduces every truth row, else linear
/// interpolation between the rows (exact for a rate that changes linearly, smeared over a row period at a step).
/// In a polled log the channel converted last before a row depends on when the poll came: the phase of the round
/// robin that fits the log best is chosen.
KnownInput known_input(const LogData& log, const TruthFile& truth, const sim::SimModel& unit);

}  // namespace driftlab::host::gap
