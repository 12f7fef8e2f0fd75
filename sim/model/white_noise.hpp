// White measurement noise at the converter input, calibrated so that the RAW codes (after quantisation) have
// the standard deviation the paper measured. Quantising adds variance lsb²/12 (Sheppard's correction), so the analog
// sigma is sqrt(raw² - 1/12) counts. The correction's error is of order exp(-2π²σ²) in the ANALOG sigma, which
// depends on where the mean falls between two codes: at the 0.5-count floor (analog 0.408) the codes' spread is
// 0.4705..0.5278 counts (-5.9 % to +5.6 %), at 0.6 ±0.7 %, at 0.7 ±0.06 %. docs/sim.md §Noise calibration.
#pragma once

#include "sim/model/rng.hpp"

namespace driftlab::sim {

/// Smallest raw standard deviation [counts] the calibration accepts: below it the quantised spread depends on
/// where the mean falls between two codes still more (at it, by up to 6 %; file comment).
inline constexpr double kMinCalibratedRawStdCounts = 0.5;

/// Analog noise sigma [counts] whose quantised codes have standard deviation `raw_std_counts` [counts].
/// 0 gives 0; values in (0, kMinCalibratedRawStdCounts) are a caller error (the model file rejects them).
double analog_sigma_for_raw_std_counts(double raw_std_counts);

/// The inverse: the standard deviation [counts] of the quantised codes of analog noise `sigma_counts`.
double raw_std_counts_for_analog_sigma(double sigma_counts);

/// Independent Gaussian samples of a fixed sigma from the channel's own substream.
class WhiteNoise {
public:
    WhiteNoise(double sigma_counts, Rng rng) : sigma_counts_(sigma_counts), rng_(rng) {}

    /// One sample [counts].
    double sample_counts() { return sigma_counts_ == 0.0 ? 0.0 : sigma_counts_ * rng_.normal(); }

    double sigma_counts() const { return sigma_counts_; }

private:
    double sigma_counts_;
    Rng rng_;
};

}  // namespace driftlab::sim
