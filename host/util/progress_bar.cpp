// A progress bar with the time left; see progress_bar.hpp.
#include "host/util/progress_bar.hpp"

#include <chrono>
#include <cstdio>
#include <string>

#include "host/util/time_left.hpp"

namespace driftlab::host {

std::function<void(double)> progress_bar() {
    const auto started = std::chrono::steady_clock::now();
    return [started](double fraction) {
        const int width = 40;
        const int filled = static_cast<int>(fraction * width);
        std::fprintf(stderr, "\r[%s%s] %3d%%  %s\033[K", std::string(filled, '#').c_str(),
                     std::string(width - filled, ' ').c_str(), static_cast<int>(fraction * 100.0),
                     time_left(fraction, seconds_since(started)).c_str());
        if (fraction >= 1.0) std::fprintf(stderr, "\n");
    };
}

}  // namespace driftlab::host
