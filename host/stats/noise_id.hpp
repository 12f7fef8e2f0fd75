// Power-law noise identification by the lag-1 autocorrelation (docs/allan.md §5), after W. J. Riley and
// C. A. Greenhall, "Power law noise identification using the lag 1 autocorrelation", EFTF 2004, as Stable32 and
// allantools' autocorr_noise_id do it. Result: alpha, the exponent of the rate PSD S_y(f) ~ f^alpha
// (2 white PM / angle quantisation, 1 flicker PM, 0 white FM = angle random walk, -1 flicker FM = bias
// instability, -2 random-walk FM = rate random walk).
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "host/stats/phase_record.hpp"

namespace driftlab::host::stats {

struct NoiseId {
    int alpha = 0;              ///< integer noise type
    double alpha_estimate = 0;  ///< the continuous estimate p (+2 for phase data) before rounding
    int differences = 0;        ///< times the series was differenced before it looked stationary
    double rho = 0;             ///< r1 / (1 + r1) of the final series
};

/// Minimum series length (after averaging by m) for which the method is used, as in allantools.
inline constexpr std::size_t kNoiseIdMinPoints = 30;

/// Identifies the noise of `samples` at averaging factor m. Phase samples are decimated by m and lose a
/// quadratic; rate samples are averaged in blocks of m and lose a line. Differencing stops once rho < 0.25 and
/// at least `dmin` and at most `dmax` differences were taken (dmax = 2 for Allan, 3 for Hadamard variances).
/// Returns nothing when fewer than kNoiseIdMinPoints points remain or the series is constant.
std::optional<NoiseId> autocorr_noise_id(std::span<const double> samples, InputKind kind, std::int64_t m, int dmin,
                                         int dmax);

/// The same on a record's longest gap-free segment: its phase for phase input, its rate (phase differences)
/// for rate input.
std::optional<NoiseId> autocorr_noise_id(const PhaseRecord& record, std::int64_t m, int dmax);

}  // namespace driftlab::host::stats
