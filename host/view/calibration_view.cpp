// Calibration table (calibration_view.hpp).
#include "host/view/calibration_view.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace driftlab::host::view {
namespace {

std::string with_interval(double value, const std::array<double, 2>& ci, int decimals) {
    char buf[96];
    if (std::isfinite(ci[0]) && std::isfinite(ci[1]))
        std::snprintf(buf, sizeof buf, "%.*f [%.*f, %.*f]", decimals, value, decimals, ci[0], decimals, ci[1]);
    else
        std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
    return buf;
}

}  // namespace

void print_calibration(std::ostream& out, const cal::Calibration& calibration, const std::string& path) {
    char line[256];
    std::snprintf(line, sizeof line, "%-8s  %-26s  %-26s  %-24s  %s\n", "channel", "C1 [counts] (95 %)",
                  "C2 [counts] (95 %)", "T [s] (95 %)", "output at rest");
    out << line;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        const cal::ChannelCalibration& ch = calibration.channels[c];
        char settled[48];
        std::snprintf(settled, sizeof settled, "%.3f (settled)", ch.model.c1 + ch.model.c2);
        const std::string rest = ch.zero ? "512 (mid-scale)" : settled;
        std::snprintf(line, sizeof line, "%-8s  %-26s  %-26s  %-24s  %s\n", kChannelNames[c],
                      with_interval(ch.model.c1, ch.c1_ci95, 3).c_str(),
                      with_interval(ch.model.c2, ch.c2_ci95, 3).c_str(),
                      with_interval(ch.model.t_s, ch.t_ci95, 1).c_str(), rest.c_str());
        out << line;
    }
    out << "calibration " << calibration.id << " of " << calibration.source << " written to " << path
        << "; upload it with `driftlab upload --port DEV --cal " << path << "`\n";
}

}  // namespace driftlab::host::view
