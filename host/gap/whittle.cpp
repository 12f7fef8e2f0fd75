// Debiased Whittle likelihood of differenced residuals; see whittle.hpp.
#include "host/gap/whittle.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

#include "host/util/fft_length.hpp"
#include "host/util/real_fft.hpp"

namespace driftlab::host::gap {

namespace {

constexpr std::size_t kMinDifferences = 16;
constexpr double kTaperFraction = 0.5;  // share of each run inside the cosine ramps (Tukey 1967)

}  // namespace

Eigen::MatrixXd orthonormal_basis(const Eigen::MatrixXd& x) {
    return Eigen::HouseholderQR<Eigen::MatrixXd>(x).householderQ() * Eigen::MatrixXd::Identity(x.rows(), x.cols());
}

namespace {

// sum_t m_t x_t e^{-i w_j t} at the periodogram's frequencies j = 1..(n-1)/2: x (its first n entries) under the part's
// taper, as the part's differences are transformed.
std::vector<std::complex<double>> tapered_transform(const PartPeriodogram& p, const std::vector<double>& x) {
    std::vector<double> v(p.length);
    for (std::size_t t = 0; t < p.length; ++t) v[t] = p.taper[t] * x[t];
    const std::vector<std::complex<double>> spec = half_spectrum(v);
    return {spec.begin() + 1, spec.begin() + 1 + static_cast<std::ptrdiff_t>(p.power.size())};
}

// The fitted columns' share of the differences (whittle.hpp, AbsorbedColumns), for the part's taper.
AbsorbedColumns absorbed_columns(const Eigen::MatrixXd& x, const PartPeriodogram& p) {
    const auto samples = static_cast<Eigen::Index>(x.rows());
    const Eigen::MatrixXd q = orthonormal_basis(x);
    AbsorbedColumns a;
    a.differences = static_cast<std::size_t>(samples - 1);
    for (Eigen::Index k = 0; k < q.cols(); ++k) {
        std::vector<double> dq(p.length);
        for (std::size_t t = 0; t < p.length; ++t) {
            const auto i = static_cast<Eigen::Index>(t);
            dq[t] = q(i + 1, k) - q(i, k);
        }
        a.alpha.push_back(tapered_transform(p, dq));
        std::vector<double> b(a.differences);
        double tail = 0.0;
        for (std::size_t j = a.differences; j-- > 0;) b[j] = tail += q(static_cast<Eigen::Index>(j + 1), k);
        a.load.push_back(std::move(b));
    }
    return a;
}

}  // namespace

PartPeriodogram part_periodogram(const std::vector<double>& e, const std::vector<bool>& in_part,
                                 const Eigen::MatrixXd* absorbed) {
    if (e.size() < 2) throw std::invalid_argument("part_periodogram: too few samples");
    PartPeriodogram p;
    p.length = smooth_length_at_most(e.size() - 1);
    std::vector<double> d(p.length, 0.0), h(p.length, 0.0);
    // Each run of consecutive in-part differences gets a split-cosine (Tukey) taper: the hard edges of the
    // interleaved blocks would otherwise leak the floor's strong high-frequency power into the low frequencies
    // that tell the slow processes apart.
    for (std::size_t a = 0; a < p.length;) {
        if (!in_part[a] || !in_part[a + 1]) {
            ++a;
            continue;
        }
        std::size_t b = a;
        while (b < p.length && in_part[b] && in_part[b + 1]) ++b;
        const std::size_t len = b - a;
        const double ramp = std::max(1.0, kTaperFraction * 0.5 * static_cast<double>(len));
        for (std::size_t t = a; t < b; ++t) {
            const double edge = std::min(static_cast<double>(t - a) + 0.5, static_cast<double>(b - t) - 0.5);
            h[t] = edge >= ramp ? 1.0 : 0.5 - 0.5 * std::cos(std::numbers::pi * edge / ramp);
            d[t] = h[t] * (e[t + 1] - e[t]);
            p.count += 1.0;
        }
        a = b;
    }
    if (p.count < kMinDifferences) throw std::invalid_argument("part_periodogram: too few differences in the part");
    double h2 = 0.0;
    for (double v : h) h2 += v * v;
    const std::vector<std::complex<double>> half = half_spectrum(d);
    for (std::size_t j = 1; 2 * j < p.length; ++j) p.power.push_back(std::norm(half[j]) / h2);
    // Taper overlap sum_t h_t h_{t+tau}: the taper's autocorrelation, zero-padded so that it does not wrap.
    const std::size_t padded = smooth_length_at_least(2 * p.length);
    h.resize(padded, 0.0);
    std::vector<std::complex<double>> spec = half_spectrum(h);
    for (auto& s : spec) s = std::norm(s);
    const std::vector<double> overlap = real_series(spec, padded);
    p.mask_overlap.resize(p.length);
    for (std::size_t tau = 0; tau < p.length; ++tau) p.mask_overlap[tau] = std::max(0.0, overlap[tau]) / h2;
    h.resize(p.length);
    p.taper = h;
    p.taper_energy = h2;
    if (absorbed) p.absorbed = absorbed_columns(*absorbed, p);
    return p;
}

std::vector<double> white_floor_autocovariance(const Smoothing& s) {
    const int n = s.window;
    std::vector<double> h(static_cast<std::size_t>(n));  // h[x], x = 0 oldest .. n - 1 newest
    for (int x = 0; x < n; ++x)
        h[static_cast<std::size_t>(x)] = s.fit_order == 0 ? 1.0 / n : (6.0 * x - 2.0 * (n - 2)) / (n * (n + 1.0));
    // Conversions from one row to the next: rounded where polled rows come at a jittered cadence.
    const int step = std::max(1, static_cast<int>(std::lround(s.outputs_per_row * s.conversions_per_output)));
    std::vector<double> r;
    for (int lag = 0; lag < n; lag += step) {
        double sum = 0.0;
        for (int x = 0; x + lag < n; ++x) sum += h[static_cast<std::size_t>(x)] * h[static_cast<std::size_t>(x + lag)];
        r.push_back(sum);
    }
    return r;
}

double white_floor_long_run_factor(const Smoothing& s) {
    const std::vector<double> r = white_floor_autocovariance(s);
    double long_run = r[0];
    for (std::size_t m = 1; m < r.size(); ++m) long_run += 2.0 * r[m];
    return long_run / r[0];
}

std::vector<double> differenced_autocovariance(const OutputSpectrum& model, const std::vector<double>& floor_acov,
                                               std::size_t n) {
    std::vector<double> c(n, 0.0);
    // White floor r(k) = white * floor_acov[k] (0 beyond its support): c(k) = 2 r(k) - r(k - 1) - r(k + 1).
    auto r = [&](std::ptrdiff_t k) {
        const auto a = static_cast<std::size_t>(std::abs(k));
        return a < floor_acov.size() ? model.white * floor_acov[a] : 0.0;
    };
    for (std::size_t k = 0; k < std::min(n, floor_acov.size() + 1); ++k) {
        const auto sk = static_cast<std::ptrdiff_t>(k);
        c[k] += 2.0 * r(sk) - r(sk - 1) - r(sk + 1);
    }
    for (const auto& a : model.ar1) {
        c[0] += 2.0 * a.variance * (1.0 - a.phi);
        double power = a.variance * (1.0 - a.phi) * (1.0 - a.phi);  // v phi^(k-1) (1 - phi)^2 at k = 1
        for (std::size_t k = 1; k < n && power > 1e-300; ++k, power *= a.phi) c[k] -= power;
    }
    c[0] += model.walk_increment_variance;
    return c;
}

std::vector<double> differenced_covariance_times(const OutputSpectrum& model, const std::vector<double>& floor_acov,
                                                 const std::vector<double>& v) {
    const std::size_t n = v.size();
    std::vector<double> out(n, model.walk_increment_variance);
    for (std::size_t t = 0; t < n; ++t) out[t] *= v[t];
    // The floor's differences are a short moving average: its few lags directly (none for a unit AR(1) or walk
    // component, whose floor is zero: ExpectedPeriodogram's).
    const std::vector<double> c_floor =
        model.white != 0.0 ? differenced_autocovariance({model.white, {}, 0.0}, floor_acov, floor_acov.size() + 1)
                           : std::vector<double>{};
    for (std::size_t t = 0; t < n; ++t)
        for (std::size_t lag = 0; lag < c_floor.size(); ++lag) {
            if (lag == 0) {
                out[t] += c_floor[0] * v[t];
                continue;
            }
            if (t >= lag) out[t] += c_floor[lag] * v[t - lag];
            if (t + lag < n) out[t] += c_floor[lag] * v[t + lag];
        }
    // An AR(1)'s geometric lags by one recursion each way: sum_{s<t} phi^(t-s-1) v_s and sum_{s>t} phi^(s-t-1) v_s.
    std::vector<double> before(n), after(n);
    for (const auto& a : model.ar1) {
        for (std::size_t t = 1; t < n; ++t) before[t] = a.phi * before[t - 1] + v[t - 1];
        after[n - 1] = 0.0;
        for (std::size_t t = n - 1; t-- > 0;) after[t] = a.phi * after[t + 1] + v[t + 1];
        const double centre = 2.0 * a.variance * (1.0 - a.phi), side = a.variance * (1.0 - a.phi) * (1.0 - a.phi);
        for (std::size_t t = 0; t < n; ++t) out[t] += centre * v[t] - side * (before[t] + after[t]);
    }
    return out;
}

std::vector<double> differenced_density(const OutputSpectrum& model, const std::vector<double>& floor_acov,
                                        std::size_t n) {
    std::vector<double> s(n);
    for (std::size_t j = 0; j < n; ++j) {
        const double w = 2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(n);
        const double c = std::cos(w);
        double level = model.white * floor_acov[0];
        for (std::size_t m = 1; m < floor_acov.size(); ++m)
            level += 2.0 * model.white * floor_acov[m] * std::cos(static_cast<double>(m) * w);
        for (const auto& a : model.ar1)
            level += a.variance * (1.0 - a.phi * a.phi) / (1.0 - 2.0 * a.phi * c + a.phi * a.phi);
        s[j] = 2.0 * (1.0 - c) * level + model.walk_increment_variance;
    }
    return s;
}

namespace {

// The expected periodogram of one component's covariance (expected_periodogram() without the floor at 1e-300): it is
// linear in the covariance, so a model's is the sum of its components'.
std::vector<double> component_periodogram(const OutputSpectrum& model, const std::vector<double>& floor_acov,
                                          const PartPeriodogram& p) {
    std::vector<double> b = differenced_autocovariance(model, floor_acov, p.length);
    for (std::size_t tau = 0; tau < p.length; ++tau) b[tau] *= p.mask_overlap[tau];
    // sum over tau = -(n-1)..n-1 of b(|tau|) e^{-i w tau} = 2 Re FFT(b)_j - b(0).
    const std::vector<std::complex<double>> spec = half_spectrum(b);
    std::vector<double> out(p.power.size());
    for (std::size_t j = 0; j < out.size(); ++j) out[j] = 2.0 * spec[j + 1].real() - b[0];
    if (p.absorbed) {
        const AbsorbedColumns& a = *p.absorbed;
        const std::size_t k_count = a.load.size();
        std::vector<std::vector<std::complex<double>>> beta(k_count);
        Eigen::MatrixXd g(k_count, k_count);
        std::vector<std::vector<double>> cb(k_count);
        for (std::size_t k = 0; k < k_count; ++k) {
            cb[k] = differenced_covariance_times(model, floor_acov, a.load[k]);
            beta[k] = tapered_transform(p, cb[k]);
        }
        for (std::size_t k = 0; k < k_count; ++k)
            for (std::size_t l = 0; l < k_count; ++l) {
                double sum = 0.0;
                for (std::size_t j = 0; j < a.differences; ++j) sum += a.load[k][j] * cb[l][j];
                g(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(l)) = sum;
            }
        for (std::size_t j = 0; j < out.size(); ++j) {
            double cross = 0.0, quadratic = 0.0;
            for (std::size_t k = 0; k < k_count; ++k) {
                cross += (std::conj(a.alpha[k][j]) * beta[k][j]).real();
                for (std::size_t l = 0; l < k_count; ++l)
                    quadratic += (std::conj(a.alpha[k][j]) * a.alpha[l][j]).real() *
                                 g(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(l));
            }
            out[j] += (quadratic - 2.0 * cross) / p.taper_energy;
        }
    }
    return out;
}

}  // namespace

ExpectedPeriodogram::ExpectedPeriodogram(const std::vector<double>& floor_acov, const PartPeriodogram& p,
                                         std::size_t kept)
    : floor_acov_(&floor_acov), p_(&p), kept_(std::max<std::size_t>(kept, 1)) {}

const std::vector<double>& ExpectedPeriodogram::unit_floor() {
    if (floor_.empty()) floor_ = component_periodogram({1.0, {}, 0.0}, *floor_acov_, *p_);
    return floor_;
}

const std::vector<double>& ExpectedPeriodogram::unit_walk() {
    if (walk_.empty()) walk_ = component_periodogram({0.0, {}, 1.0}, *floor_acov_, *p_);
    return walk_;
}

const std::vector<double>& ExpectedPeriodogram::unit_ar1(double phi) {
    ++clock_;
    for (Kept& k : ar1_)
        if (k.phi == phi) {
            k.last_use = clock_;
            return k.values;
        }
    if (ar1_.size() == kept_)
        ar1_.erase(std::min_element(ar1_.begin(), ar1_.end(),
                                    [](const Kept& a, const Kept& b) { return a.last_use < b.last_use; }));
    OutputSpectrum unit;
    unit.ar1.push_back({1.0, phi});
    ar1_.push_back({phi, clock_, component_periodogram(unit, *floor_acov_, *p_)});
    return ar1_.back().values;
}

std::vector<double> ExpectedPeriodogram::operator()(const OutputSpectrum& model) {
    std::vector<double> out(p_->power.size(), 0.0);
    const auto add = [&](double weight, const std::vector<double>& unit) {
        for (std::size_t j = 0; j < out.size(); ++j) out[j] += weight * unit[j];
    };
    if (model.white != 0.0) add(model.white, unit_floor());
    for (const auto& a : model.ar1)
        if (a.variance != 0.0) add(a.variance, unit_ar1(a.phi));
    if (model.walk_increment_variance != 0.0) add(model.walk_increment_variance, unit_walk());
    for (double& v : out) v = std::max(v, 1e-300);
    return out;
}

std::vector<double> expected_periodogram(const OutputSpectrum& model, const std::vector<double>& floor_acov,
                                         const PartPeriodogram& p) {
    return ExpectedPeriodogram(floor_acov, p)(model);
}

double whittle_nll(const PartPeriodogram& p, const std::vector<double>& expected, std::vector<double>* terms) {
    double sum = 0.0;
    if (terms) terms->resize(p.power.size());
    for (std::size_t j = 0; j < p.power.size(); ++j) {
        const double t = std::log(expected[j]) + p.power[j] / expected[j];
        sum += t;
        if (terms) (*terms)[j] = t;
    }
    return sum;
}

}  // namespace driftlab::host::gap
