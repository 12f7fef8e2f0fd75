// Level-step test; see level_step.hpp.
#include "host/gap/level_step.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include <unsupported/Eigen/FFT>

#include "host/gap/candidates.hpp"
#include "host/gap/replicates.hpp"
#include "host/gap/spectral_fit.hpp"

namespace driftlab::host::gap {

namespace {

constexpr double kEdgeFraction = 0.02;  // a step this close to an end is half absorbed by the eq. 1 fit
constexpr double kMemoryShare = 0.1;    // the whitening's memory, as a share of the log

struct Largest {
    std::size_t index = 0;  ///< difference index: the step lies between samples index and index + 1
    double t = 0.0;         ///< standardised statistic
    double size = 0.0;      ///< estimated impulse [counts]
};

// The largest |T| of the residual `r` (n + 1 samples) under the differenced spectral density `density` of its
// mirror extension (length 2n). The mirror makes the series circular without a jump where it wraps; the whitening
// filter then acts as on an infinite series, and the ends are kept clear of the maximum anyway.
Largest largest_step(const std::vector<double>& r, const std::vector<double>& density) {
    const std::size_t m = density.size(), n = m / 2;
    std::vector<double> d(m);
    for (std::size_t t = 0; t < n; ++t) {
        d[t] = r[t + 1] - r[t];
        d[m - 1 - t] = -d[t];
    }
    Eigen::FFT<double> fft;
    std::vector<std::complex<double>> spec;
    fft.fwd(spec, d);
    double kappa = 0.0;
    spec[0] = 0.0;  // the mean difference carries no step location
    for (std::size_t j = 1; j < m; ++j) {
        spec[j] /= density[j];
        kappa += 1.0 / density[j];
    }
    kappa /= static_cast<double>(m);
    std::vector<double> u;
    fft.inv(u, spec);
    Largest best;
    const auto edge = std::max<std::size_t>(2, static_cast<std::size_t>(kEdgeFraction * static_cast<double>(n)));
    for (std::size_t t = edge; t + edge < n; ++t) {
        const double stat = std::abs(u[t]) / std::sqrt(kappa);
        if (stat > best.t) best = {t, stat, u[t] / kappa};
    }
    return best;
}

}  // namespace

LevelStep test_level_step(const GapModel& model, Channel c, const std::vector<double>& t_s, const std::vector<double>& y,
                          const std::vector<std::string>& spectral_effects, const std::vector<double>& spectral_params,
                          int replicates, std::uint64_t seed, int threads, double alpha) {
    const std::size_t i = channel_index(c);
    const std::vector<double> mean = model_mean_counts(model, c, t_s);
    std::vector<double> r(y.size());
    for (std::size_t k = 0; k < r.size(); ++k) r[k] = y[k] - mean[k];
    const std::vector<bool> all(r.size(), true);
    const SpectralFit fit = fit_spectral(spectral_effects, c, model, part_periodogram(r, all), spectral_params);
    // The whitening compares levels before and after each instant over at most a tenth of the log: a slight random
    // walk (its filter's memory is sqrt(white / increment) samples) keeps a stationary model's 1/w^2 low-frequency
    // gain from weighing the whole log's mean, which the eq. 1 fit has already bent.
    const std::size_t n = smooth_length_at_most(r.size() - 1);
    const std::vector<double> floor_acov = white_floor_autocovariance(model.smoothing);
    OutputSpectrum spectrum = model_spectrum(spectral_effects, c, fit.params, model, fit.white);
    spectrum.walk_increment_variance += fit.white * floor_acov[0] * std::pow(kMemoryShare * static_cast<double>(n), -2.0);
    const std::vector<double> density = differenced_density(spectrum, floor_acov, 2 * n);
    const Largest real = largest_step(r, density);
    std::array<bool, kChannelCount> only{};
    only[i] = true;
    const Eigen::MatrixXd null = simulate_replicates(model, t_s, only, replicates, seed, threads, [&](const SimOutput& sim) {
        std::vector<double> rr(sim[i].size());
        for (std::size_t k = 0; k < rr.size(); ++k) rr[k] = sim[i][k] - mean[k];
        return std::vector<double>{largest_step(rr, density).t};
    });
    LevelStep out;
    out.tested = true;
    out.channel = c;
    out.t_s = 0.5 * (t_s[real.index] + t_s[real.index + 1]);
    out.size_counts = real.size;
    out.statistic = real.t;
    const auto exceed = (null.col(0).array() >= real.t).count();
    out.p_value = (1.0 + static_cast<double>(exceed)) / (1.0 + static_cast<double>(replicates));
    out.significant = out.p_value <= alpha;
    return out;
}

}  // namespace driftlab::host::gap
