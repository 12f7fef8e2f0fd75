// The discrete Fourier transform of real series, by FFTW (Frigo & Johnson, Proc. IEEE 93(2), 2005): every spectrum
// the host computes goes through these two calls. Each thread keeps its own plans (one per length and direction,
// the few used last), so the spectral likelihood's thousands of transforms of one length plan once. Plans are made
// with FFTW_ESTIMATE, never by timing trial transforms, so one build on one machine gives the same digits every run;
// DRIFTLAB_FFT_PORTABLE=1 gives the same digits on CPUs of other vector widths too (docs/performance.md §FFT).
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace driftlab::host {

/// Bins 0 .. n/2 (n/2 + 1 of them, n = x.size()) of sum_t x_t e^{-2 pi i j t / n}; the upper bins mirror them. An
/// empty series has none, one point is its own transform.
std::vector<std::complex<double>> half_spectrum(const std::vector<double>& x);

/// The real series of length n whose half_spectrum() is `half` (its n/2 + 1 bins; the imaginary parts of bin 0 and,
/// for even n, bin n/2 are taken as 0, as a real series has them): the inverse transform, scaled by 1/n. Throws
/// std::invalid_argument when `half` does not hold n/2 + 1 bins.
std::vector<double> real_series(const std::vector<std::complex<double>>& half, std::size_t n);

}  // namespace driftlab::host
