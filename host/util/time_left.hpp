// Elapsed and remaining time of a long run, as text for its progress line.
#pragma once

#include <chrono>
#include <string>

namespace driftlab::host {

/// Seconds of the steady clock since `start`: a run's elapsed wall time.
double seconds_since(std::chrono::steady_clock::time_point start);

/// `seconds` as a person reads a duration: "45 s", "2 min 05 s", "1 h 05 min" (rounded to the unit shown last).
std::string format_duration(double seconds);

/// "about 2 min 05 s left" for a run `fraction` done after `elapsed_s`, the rest taken at the pace so far; "" while
/// the pace is not yet known (under 1 s or under 1 % done) and once under half a second is left.
std::string time_left(double fraction, double elapsed_s);

}  // namespace driftlab::host
