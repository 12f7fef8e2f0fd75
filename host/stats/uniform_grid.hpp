// Time-stamped samples onto the uniform tau0 grid the Allan statistics need, with missing samples as NaN
// (docs/allan.md §7): a recorder reconnect or lost frames become an explicit gap, never a silent splice.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace driftlab::host::stats {

struct UniformSeries {
    double tau0_s = 0.0;         ///< grid spacing [s]
    double t0_s = 0.0;           ///< time of grid index 0 [s]
    std::vector<double> values;  ///< one per grid slot; NaN where no sample fell
    std::size_t missing = 0;     ///< slots without a sample (gaps)
    std::size_t packed = 0;      ///< samples placed 2 or more slots after their time (rows faster than tau0)
    std::size_t most_late = 0;   ///< the largest such displacement [slots]
};

/// Median spacing of strictly increasing times [s]; 0 for fewer than two samples.
double median_spacing_s(std::span<const double> t_s);

/// Mean spacing of increasing times [s]; 0 for fewer than two samples.
double mean_spacing_s(std::span<const double> t_s);

/// How far a spacing may be from another and still agree (jittered host time stamps).
constexpr double kSpacingTolerance = 0.05;

/// Whether spacing `a_s` lies within kSpacingTolerance of `b_s`; the test of period_agrees.
bool spacing_agrees(double a_s, double b_s);

/// Whether `period_s` agrees within 5 % (jittered host time stamps) with the median or the mean spacing of `t_s`:
/// the mean for rows that come in bursts (an MPU6050 read 100 times a second in bursts 2 ms apart).
bool period_agrees(std::span<const double> t_s, double period_s);

/// The rows' spacing for messages: "b s apart (median; mean c s)".
std::string spacing_text(std::span<const double> t_s);

/// When `tau0_s` does not agree (period_agrees), a sentence saying so ("--tau0 a s, but the time column's rows are
/// b s apart (median; mean c s)"); nothing when it does.
std::optional<std::string> tau0_disagreement(std::span<const double> t_s, double tau0_s);

/// The grid period for rows given without one: their median spacing, or the mean where a grid at the median would
/// be more than half gaps (1 - median / mean > 1/2): rows in bursts, such as the MPU6050 recording's 100 a second
/// in bursts 2 ms apart (median 2 ms, mean 10 ms), where the median is the burst's spacing, not the rows' rate.
/// Lost frames raise the mean as well, but leave the median the rows' period; only half the record lost passes for
/// bursts.
double grid_period_s(std::span<const double> t_s);

/// Places sample k at slot max(slot_{k-1} + 1, round((t_k - t_0) / tau0)): samples that come early or in
/// bursts take the next free slot (none is ever dropped), a sample that comes late leaves the slots it skipped
/// empty (NaN), so a real gap is never closed up. Throws std::invalid_argument when the sizes differ, tau0 <= 0, or the
/// grid would exceed 20x the sample count (tau0 far too small for these times).
UniformSeries to_uniform_grid(std::span<const double> t_s, std::span<const double> values, double tau0_s);

}  // namespace driftlab::host::stats
