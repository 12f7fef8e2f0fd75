// The second-order summaries the gap battery uses, written for speed on many replicates: overlapping Allan
// deviation on an octave grid, octave-band periodogram power, octave-band coherence between two series and octave
// lag-band autocorrelation.
// docs/gap.md §Statistics.
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace driftlab::host::stats {

/// Overlapping Allan deviation of the rate series `y` (sample spacing tau0) at m = 1, 2, 4, ... while m <= max_m
/// (NIST SP 1065 eq. 14, via the phase x = cumsum(y) tau0). Returns one value per m [unit of y].
std::vector<double> octave_oadev(const std::vector<double>& y, std::size_t max_m);

/// The transform both band summaries start from: `y` with its mean removed, Hann window, zero-padded to a power of
/// two. Computed once per series, it serves its own band power and its coherence with every other series.
struct BandSpectrum {
    std::vector<std::complex<double>> bins;  ///< FFT of the windowed series below Nyquist: its first nfft / 2 bins
    std::vector<double> band_energy;         ///< sum of |X_k|^2 in each band of octave_band_power()
    std::size_t length = 0;                  ///< samples of the series
};
BandSpectrum band_spectrum(const std::vector<double>& y);

/// Mean periodogram power of the series of `s` in octave bands of frequency index, from Nyquist down: band j covers
/// [K/2^(j+1), K/2^j) with K = nfft/2, while the band's lower index is >= 2. Power is per bin in
/// [unit^2 * samples]; only ratios between logs of equal length matter here.
std::vector<double> octave_band_power(const BandSpectrum& s);

/// Bands of fewer bins hold too few independent ones (a Hann window couples neighbours) for a coherence: with one,
/// it is 1 whatever the series.
inline constexpr std::size_t kCoherenceMinBins = 8;

/// Magnitude-squared coherence |sum X conj(Y)|^2 / (sum |X|^2 sum |Y|^2) of two series of equal length in the
/// bands of octave_band_power() of at least kCoherenceMinBins bins, in [0, 1]: how much of one series each band of
/// the other predicts linearly, at lags short against the inverse of the band's width (a longer lag turns the phase
/// across the band and averages it away).
/// Its bias with no shared content is about 1 / (independent bins in the band).
std::vector<double> octave_band_coherence(const BandSpectrum& a, const BandSpectrum& b);

/// Mean autocorrelation r(k) = sum e_i e_{i+k} / sum e_i^2 of `y` (mean removed) over lag bands [1], [2,3],
/// [4,7], ... while the band's upper lag is <= max_lag.
std::vector<double> octave_lag_acf(const std::vector<double>& y, std::size_t max_lag);

}  // namespace driftlab::host::stats
