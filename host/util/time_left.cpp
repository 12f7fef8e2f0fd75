// Progress-line durations; see time_left.hpp.
#include "host/util/time_left.hpp"

#include <cmath>
#include <cstdio>

namespace driftlab::host {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string format_duration(double seconds) {
    char text[64];
    const long long s = std::llround(std::fmax(seconds, 0.0));
    if (s < 60) {
        std::snprintf(text, sizeof text, "%lld s", s);
    } else if (s < 3600) {
        std::snprintf(text, sizeof text, "%lld min %02lld s", s / 60, s % 60);
    } else {
        const long long m = std::llround(std::fmax(seconds, 0.0) / 60.0);
        std::snprintf(text, sizeof text, "%lld h %02lld min", m / 60, m % 60);
    }
    return text;
}

std::string time_left(double fraction, double elapsed_s) {
    if (!(fraction >= 0.01 && fraction < 1.0) || !(elapsed_s >= 1.0)) return "";
    const double left_s = elapsed_s * (1.0 - fraction) / fraction;
    return left_s < 0.5 ? "" : "about " + format_duration(left_s) + " left";
}

}  // namespace driftlab::host
