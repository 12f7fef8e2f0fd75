// Where the unit stands: a trailing window of readings that is quiet on every axis (its spread no more than white
// noise's, at 99 %, and its mean at the filter's bias estimate within three standard deviations). A robot cruising
// at constant speed reads the same as one standing; the filter's velocity gate (PlanarEkf::update_zero_velocity)
// tells them apart. docs/nav.md §Stops.
#pragma once

#include <array>
#include <cstddef>
#include <deque>
#include <vector>

#include "host/nav/planar_ekf.hpp"

namespace driftlab::host::nav {

class StopDetector {
public:
    /// A window of `window_s` seconds; `reading_sd` each axis's white noise standard deviation in one reading [SI].
    StopDetector(double window_s, const std::array<double, 3>& reading_sd);

    void push(double t_s, const ImuReading& r);
    /// Whether the window is full and quiet about `bias` (standard deviations `bias_sd`).
    bool quiet(const std::array<double, 3>& bias, const std::array<double, 3>& bias_sd) const;

private:
    struct Entry {
        double t_s;
        std::array<double, 3> v;
    };
    double window_s_;
    std::array<double, 3> sd_;
    std::deque<Entry> window_;
    std::array<double, 3> sum_{}, sum2_{};
    mutable std::vector<double> variance_bound_;  // chi-square 99 % over its degrees of freedom, by window size
};

}  // namespace driftlab::host::nav
