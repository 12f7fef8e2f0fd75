// Octave-grid ADEV, band power, band coherence and lag-band autocorrelation; see spectral.hpp.
#include "host/stats/spectral.hpp"

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "host/stats/autocorrelation.hpp"
#include "host/util/real_fft.hpp"

namespace driftlab::host::stats {

namespace {

std::size_t next_pow2(std::size_t n) {
    std::size_t p = 1;
    while (p < n) p <<= 1;
    return p;
}

std::vector<double> demeaned(const std::vector<double>& y) {
    double mean = 0.0;
    for (double v : y) mean += v;
    mean /= static_cast<double>(y.size());
    std::vector<double> out(y.size());
    for (std::size_t i = 0; i < y.size(); ++i) out[i] = y[i] - mean;
    return out;
}

// The octave bands of frequency index below Nyquist (`half` = nfft / 2 bins), from Nyquist down: band j covers
// [hi / 2, hi) with hi = half / 2^j, while its lower index is >= min_lo. f(j, lo, hi) per band.
template <class F>
void for_each_octave_band(std::size_t half, std::size_t min_lo, F&& f) {
    std::size_t j = 0;
    for (std::size_t hi = half; hi / 2 >= min_lo; hi /= 2) f(j++, hi / 2, hi);
}

}  // namespace

std::vector<double> octave_oadev(const std::vector<double>& y, std::size_t max_m) {
    // tau0 cancels between x = cumsum(y) tau0 and the 1/tau^2 of the estimator, so work with tau0 = 1.
    std::vector<double> x(y.size() + 1, 0.0);
    for (std::size_t i = 0; i < y.size(); ++i) x[i + 1] = x[i] + y[i];
    std::vector<double> out;
    for (std::size_t m = 1; m <= max_m && 2 * m < x.size(); m *= 2) {
        double sum = 0.0;
        const std::size_t terms = x.size() - 2 * m;
        for (std::size_t k = 0; k < terms; ++k) {
            const double d = x[k + 2 * m] - 2.0 * x[k + m] + x[k];
            sum += d * d;
        }
        out.push_back(std::sqrt(sum / (2.0 * static_cast<double>(m * m) * static_cast<double>(terms))));
    }
    return out;
}

BandSpectrum band_spectrum(const std::vector<double>& y) {
    const std::vector<double> e = demeaned(y);
    std::vector<double> w(next_pow2(e.size()), 0.0);
    const double n = static_cast<double>(e.size());
    for (std::size_t i = 0; i < e.size(); ++i)
        w[i] = e[i] * (0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * (static_cast<double>(i) + 0.5) / n));
    BandSpectrum s;
    s.length = e.size();
    // The bands use the bins below Nyquist alone (a real series' upper half mirrors them); the battery keeps eight
    // spectra per replicate in flight, and whole transforms had doubled what they hold.
    s.bins = half_spectrum(w);
    s.bins.resize(w.size() / 2);
    for_each_octave_band(s.bins.size(), 2, [&](std::size_t, std::size_t lo, std::size_t hi) {
        double sum = 0.0;
        for (std::size_t k = lo; k < hi; ++k) sum += std::norm(s.bins[k]);
        s.band_energy.push_back(sum);
    });
    return s;
}

std::vector<double> octave_band_power(const BandSpectrum& s) {
    std::vector<double> out;
    for_each_octave_band(s.bins.size(), 2, [&](std::size_t j, std::size_t lo, std::size_t hi) {
        out.push_back(s.band_energy[j] / static_cast<double>(hi - lo) / static_cast<double>(s.length));
    });
    return out;
}

std::vector<double> octave_band_coherence(const BandSpectrum& a, const BandSpectrum& b) {
    std::vector<double> out;
    for_each_octave_band(a.bins.size(), kCoherenceMinBins, [&](std::size_t j, std::size_t lo, std::size_t hi) {
        std::complex<double> cross = 0.0;
        for (std::size_t k = lo; k < hi; ++k) cross += a.bins[k] * std::conj(b.bins[k]);
        const double pa = a.band_energy[j], pb = b.band_energy[j];
        out.push_back(pa > 0.0 && pb > 0.0 ? std::norm(cross) / (pa * pb) : 0.0);
    });
    return out;
}

std::vector<double> octave_lag_acf(const std::vector<double>& y, std::size_t max_lag) {
    const std::vector<double> acov = stats::biased_autocovariance(demeaned(y), max_lag);
    std::vector<double> out;
    // A constant series has no correlation to speak of; keep the band count fixed for the caller.
    const double r0 = acov[0] > 0.0 ? acov[0] : std::numeric_limits<double>::infinity();
    for (std::size_t lo = 1; 2 * lo - 1 <= max_lag && 2 * lo - 1 < acov.size(); lo *= 2) {
        double sum = 0.0;
        for (std::size_t k = lo; k < 2 * lo; ++k) sum += acov[k] / r0;
        out.push_back(sum / static_cast<double>(lo));
    }
    return out;
}

}  // namespace driftlab::host::stats
