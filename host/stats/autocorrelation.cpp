// Autocovariance and autocorrelation time; see autocorrelation.hpp.
#include "host/stats/autocorrelation.hpp"

#include <algorithm>
#include <complex>

#include "host/util/fft_length.hpp"
#include "host/util/real_fft.hpp"

namespace driftlab::host::stats {

std::vector<double> biased_autocovariance(const std::vector<double>& w, std::size_t max_lag) {
    const std::size_t n = w.size();
    if (n == 0) return {};
    max_lag = std::min(max_lag, n - 1);
    // Zero-padded to N + max_lag, the circular correlation equals the linear one up to max_lag; a 2-3-5 length is
    // close above it (a power of two >= 2N was up to four times as long), and an even one keeps the real
    // transform at half length.
    const std::size_t size = 2 * smooth_length_at_least((n + max_lag + 1) / 2);
    std::vector<double> padded(size, 0.0);
    std::copy(w.begin(), w.end(), padded.begin());
    std::vector<std::complex<double>> spectrum = half_spectrum(padded);
    for (auto& x : spectrum) x = std::norm(x);
    const std::vector<double> circular = real_series(spectrum, size);
    std::vector<double> r(max_lag + 1);
    for (std::size_t d = 0; d <= max_lag; ++d) r[d] = circular[d] / static_cast<double>(n);
    return r;
}

AutocorrelationTime integrated_autocorrelation_time(const std::vector<double>& rho, double c) {
    AutocorrelationTime out;
    double tau = 1.0;
    for (std::size_t d = 1; d < rho.size(); ++d) {
        tau += 2.0 * rho[d];
        if (static_cast<double>(d) >= c * tau) {
            out.tau = std::max(1.0, tau);
            out.window = d;
            return out;
        }
    }
    out.tau = std::max(1.0, tau);
    out.window = rho.empty() ? 0 : rho.size() - 1;
    out.window_found = false;
    return out;
}

}  // namespace driftlab::host::stats
