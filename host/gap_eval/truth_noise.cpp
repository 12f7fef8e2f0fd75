// The random truth generators: Kasdin 1/f noise, a wandering-correlation OU, a Student-t walk. truth.hpp.
#include <cmath>
#include <complex>

#include "host/gap_eval/truth.hpp"
#include "host/util/real_fft.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::host::gap {

namespace {

void scale_to_sd(std::vector<double>& v, double sd) {
    double m = 0, s = 0;
    for (double x : v) m += x;
    m /= static_cast<double>(v.size());
    for (double x : v) s += (x - m) * (x - m);
    s = std::sqrt(s / static_cast<double>(v.size()));
    for (double& x : v) x = s > 0 ? (x - m) * sd / s : 0.0;
}

}  // namespace

std::vector<double> truth_kasdin_flicker(const std::vector<double>& t_s, double size_counts, std::uint64_t noise_seed) {
    // Kasdin (Proc. IEEE 83(5), 1995): white noise shaped in frequency by f^(-alpha/2), alpha = 1, on a record
    // twice as long as needed (half discarded) so the circular wrap does not show.
    sim::Rng rng(noise_seed, 0x73);
    const std::size_t n = t_s.size();
    std::size_t nfft = 1;
    while (nfft < 2 * n) nfft <<= 1;
    std::vector<double> white(nfft);
    for (double& w : white) w = rng.normal();
    std::vector<std::complex<double>> spec = half_spectrum(white);
    spec[0] = 0.0;
    for (std::size_t k = 1; k < spec.size(); ++k) {
        const double f = static_cast<double>(k) / static_cast<double>(nfft);
        spec[k] *= 1.0 / std::sqrt(f);
    }
    const std::vector<double> shaped = real_series(spec, nfft);
    std::vector<double> out(shaped.begin(), shaped.begin() + static_cast<std::ptrdiff_t>(n));
    scale_to_sd(out, size_counts);
    return out;
}

std::vector<double> truth_wandering_ou(const std::vector<double>& t_s, double size_counts, std::uint64_t seed,
                                       std::uint64_t noise_seed) {
    // dx = -x/tau(t) dt + sqrt(2/tau(t)) dW by Euler-Maruyama with 8 substeps; tau(t) wanders +-30 % slowly.
    // tau0 is log-uniform in [L/200, L/30]: with its wander it stays below L/20, the longest correlation time a
    // static log can tell from flicker or a random walk (gap-method §4; the diagnosis calls a longer one a close
    // call), so the generator stands for a Gauss-Markov process the log can identify.
    sim::Rng shape(seed, 0x74);
    const double span_s = t_s.back() - t_s.front();
    const double tau0 = span_s * std::exp(std::log(1.0 / 200.0) + std::log(200.0 / 30.0) * shape.uniform());
    const double wander_period = span_s * (0.3 + 0.4 * shape.uniform());
    sim::Rng rng(noise_seed, 0x84);
    std::vector<double> out(t_s.size());
    double x = rng.normal();
    double t = t_s.front();
    for (std::size_t k = 0; k < t_s.size(); ++k) {
        const double h = (k ? t_s[k] - t_s[k - 1] : 0.0) / 8.0;
        for (int s = 0; s < 8 && h > 0; ++s) {
            const double tau = tau0 * (1.0 + 0.3 * std::sin(2.0 * 3.14159265358979 * t / wander_period));
            x += -x / tau * h + std::sqrt(2.0 * h / tau) * rng.normal();
            t += h;
        }
        out[k] = x * size_counts;
    }
    return out;
}

std::vector<double> truth_student_walk(const std::vector<double>& t_s, double size_counts, std::uint64_t noise_seed) {
    // Steps are Student-t with nu = 4 (normal / sqrt(chi2_4 / 4)), scaled to unit variance (nu / (nu - 2) = 2);
    // size_counts is the walk's standard deviation reached at the end of the log.
    sim::Rng rng(noise_seed, 0x75);
    const double n = static_cast<double>(t_s.size());
    const double step_sd = size_counts / std::sqrt(n);
    std::vector<double> out(t_s.size());
    double x = 0.0;
    for (std::size_t k = 0; k < t_s.size(); ++k) {
        double chi2 = 0.0;
        for (int i = 0; i < 4; ++i) {
            const double z = rng.normal();
            chi2 += z * z;
        }
        x += step_sd * rng.normal() / std::sqrt(chi2 / 4.0) / std::sqrt(2.0);
        out[k] = x;
    }
    return out;
}

std::vector<double> truth_supply_wander(const std::vector<double>& t_s, double size, std::uint64_t seed,
                                        std::uint64_t noise_seed) {
    // A Gauss-Markov drive of correlation time tau1 through a first-order lag tau2 = tau1 / 4 (the regulator's
    // reference wandering, seen through its output filter and the board's thermal mass): a second-order process,
    // not the candidate's one Gauss-Markov. tau1 is log-uniform in [L/40, L/8], minutes on the benchmark's logs.
    sim::Rng shape(seed, 0x91);
    const double span_s = t_s.back() - t_s.front();
    const double tau1 = span_s * std::exp(std::log(1.0 / 40.0) + std::log(5.0) * shape.uniform());
    const double tau2 = tau1 / 4.0;
    sim::Rng rng(noise_seed, 0x92);
    std::vector<double> out(t_s.size());
    double drive = rng.normal(), lagged = drive;
    for (std::size_t k = 0; k < t_s.size(); ++k) {
        const double dt = k == 0 ? 0.0 : t_s[k] - t_s[k - 1];
        const double phi1 = std::exp(-dt / tau1), phi2 = std::exp(-dt / tau2);
        drive = phi1 * drive + std::sqrt(1.0 - phi1 * phi1) * rng.normal();
        lagged = phi2 * lagged + (1.0 - phi2) * drive;
        out[k] = lagged;
    }
    scale_to_sd(out, size);
    return out;
}

}  // namespace driftlab::host::gap
