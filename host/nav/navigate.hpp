// One navigation run over a log: the four variants side by side, each named in the output (docs/nav.md §Variants):
//   raw          a constant bias from the first seconds at rest, dead reckoning;
//   forward      eq. 1 subtracted sample by sample (the paper's forward correction), dead reckoning;
//   ekf          raw's input, the filter estimating the biases with the aids;
//   forward+ekf  eq. 1 as a known input, the filter estimating what is left.
// The dead-reckoning variants run the same filter with biases that do not walk and no aid, so that they too carry
// the covariance they believe in.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "host/log/log_data.hpp"
#include "host/log/truth_file.hpp"
#include "host/nav/unit_drift.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::host::nav {

struct AidOptions {
    bool zupt = false;              ///< zero velocity (and the biases read) at detected stops
    bool odometry = false;          ///< wheel speed: the truth's, with white noise of odometry_sd_mps
    bool fixes = false;             ///< absolute position: the truth's every fix_every_s, with noise of fix_sd_m
    double odometry_sd_mps = 0.02;  ///< [m/s]
    double fix_every_s = 60.0;      ///< [s]
    double fix_sd_m = 0.5;          ///< [m] per axis
    std::uint64_t seed = 1;         ///< the aids' noise
};

/// Switches on the aid `name` (zupt, odometry, fixes; none switches on nothing); false for any other name.
bool enable_aid(AidOptions& aid, const std::string& name);

struct NavOptions {
    /// Added to the filter variants' bias walks [(rad/s)^2/s, (m/s^2)^2/s per axis]: the effects gap found.
    std::array<double, kNavAxes> effects_bias_psd{};
    std::string effects_used;    ///< their names, for the notes ("" for none)
    double rest_s = 10.0;        ///< the first seconds, where the unit stands (raw's bias, the filters' start)
    double stop_window_s = 1.0;  ///< a stop is this long a window of quiet readings
    AidOptions aid;
};

/// A stretch the filter found the unit standing [s since power-on].
struct Stop {
    double from_s = 0.0, to_s = 0.0;
};

struct Track {
    std::string name;
    std::vector<double> x_m, y_m, heading_deg;  ///< per row; heading unwrapped, counter-clockwise, 0 at the start
    std::vector<double> heading_sd_deg, position_sd_m;  ///< the filter's own standard deviations
    std::vector<double> nees;                           ///< per row against the truth (empty without one); NaN at row 0
    std::vector<Stop> stops;                            ///< where it detected the unit standing
    std::size_t zero_velocity_updates = 0, odometry_updates = 0, position_fixes = 0;
    bool filter = false;  ///< estimates its biases and takes the aids
};

struct NavRun {
    std::vector<double> t_s;  ///< the log's rows [s since power-on]
    std::vector<Track> tracks;
    std::vector<std::string> notes;
    bool heading_only = false;  ///< no accelerometers: the position stays at the origin and is not scored
};

/// The truth a run is scored against: the truth file's rows matched to the log's, or a unit at rest throughout; in
/// the frame of the log's first row (where navigation starts: origin, heading 0), whatever rows the log kept.
class NavTruth {
public:
    /// At rest throughout (a static recording).
    NavTruth() = default;
    /// `rows`: the truth row of each log row (match_truth_rows).
    NavTruth(const TruthFile& file, std::vector<std::size_t> rows);

    double x(std::size_t i) const;
    double y(std::size_t i) const;
    double heading_deg(std::size_t i) const;
    double speed(std::size_t i) const { return file_ ? file_->speed_mps[rows_[i]] : 0.0; }

private:
    const TruthFile* file_ = nullptr;
    std::vector<std::size_t> rows_;
    double x0_ = 0.0, y0_ = 0.0, heading0_deg_ = 0.0, cos0_ = 1.0, sin0_ = 0.0;
};

/// Runs the variants over `log` read through `unit`'s front ends; the forward ones only with `drift`. The aids from
/// the truth need `truth` (UsageError otherwise: the log cannot support them).
NavRun navigate(const LogData& log, const sim::SimModel& unit, const std::optional<UnitDrift>& drift,
                const std::optional<NavTruth>& truth, const NavOptions& options);

}  // namespace driftlab::host::nav
