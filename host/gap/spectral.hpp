// The second-order summaries the gap battery uses, written for speed on many replicates: overlapping Allan
// deviation on an octave grid, octave-band periodogram power and octave lag-band autocorrelation.
// docs/gap.md §Statistics.
#pragma once

#include <cstddef>
#include <vector>

namespace driftlab::host::gap {

/// Overlapping Allan deviation of the rate series `y` (sample spacing tau0) at m = 1, 2, 4, ... while m <= max_m
/// (NIST SP 1065 eq. 14, via the phase x = cumsum(y) tau0). Returns one value per m [unit of y].
std::vector<double> octave_oadev(const std::vector<double>& y, std::size_t max_m);

/// Mean periodogram power of `y` (mean removed, Hann window, zero-padded to a power of two) in octave bands of
/// frequency index, from Nyquist down: band j covers [K/2^(j+1), K/2^j) with K = nfft/2, while the band's lower
/// index is >= 2. Power is per bin in [unit^2 * samples]; only ratios between logs of equal length matter here.
std::vector<double> octave_band_power(const std::vector<double>& y);

/// Mean autocorrelation r(k) = sum e_i e_{i+k} / sum e_i^2 of `y` (mean removed) over lag bands [1], [2,3],
/// [4,7], ... while the band's upper lag is <= max_lag.
std::vector<double> octave_lag_acf(const std::vector<double>& y, std::size_t max_lag);

}  // namespace driftlab::host::gap
