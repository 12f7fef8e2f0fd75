// Noise calibration through the quantiser; see white_noise.hpp.
#include "sim/model/white_noise.hpp"

#include <cmath>

namespace driftlab::sim {

double analog_sigma_for_raw_std_counts(double raw_std_counts) {
    if (raw_std_counts == 0.0) return 0.0;
    return std::sqrt(raw_std_counts * raw_std_counts - 1.0 / 12.0);
}

double raw_std_counts_for_analog_sigma(double sigma_counts) {
    if (sigma_counts == 0.0) return 0.0;
    return std::sqrt(sigma_counts * sigma_counts + 1.0 / 12.0);
}

}  // namespace driftlab::sim
