// Greenhall-Riley equivalent degrees of freedom and chi-square intervals (docs/allan.md §4).
#include "host/stats/edf.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "host/stats/chi_square.hpp"

namespace driftlab::host::stats {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kJMax = 100;  // the paper's truncation of the basic sum

// sw(t): generalized autocovariance of the phase for noise alpha (Greenhall-Riley eq. 7), up to a constant.
double sw(double t, int alpha) {
    const double at = std::fabs(t);
    switch (alpha) {
    case 2: return -at;
    case 1: return t == 0.0 ? 0.0 : t * t * std::log(at);
    case 0: return at * at * at;
    case -1: return t == 0.0 ? 0.0 : std::pow(t, 4) * std::log(at);
    case -2: return std::pow(at, 5);
    case -3: return t == 0.0 ? 0.0 : std::pow(t, 6) * std::log(at);
    case -4: return std::pow(at, 7);
    default: return std::numeric_limits<double>::quiet_NaN();
    }
}

// sx(t): after the averaging filter of factor F (eq. 8); F = infinity is the limit of the unmodified filter.
double sx(double t, double f, int alpha) {
    if (std::isinf(f)) return sw(t, alpha + 2);
    return f * f * (2.0 * sw(t, alpha) - sw(t - 1.0 / f, alpha) - sw(t + 1.0 / f, alpha));
}

// sz(t): after the d-th difference (eq. 9): binomial coefficients of (1 - B)^d folded symmetrically.
double sz(double t, double f, int alpha, int d) {
    switch (d) {
    case 1: return 2.0 * sx(t, f, alpha) - sx(t - 1.0, f, alpha) - sx(t + 1.0, f, alpha);
    case 2:
        return 6.0 * sx(t, f, alpha) - 4.0 * (sx(t - 1.0, f, alpha) + sx(t + 1.0, f, alpha)) + sx(t - 2.0, f, alpha) +
               sx(t + 2.0, f, alpha);
    case 3:
        return 20.0 * sx(t, f, alpha) - 15.0 * (sx(t - 1.0, f, alpha) + sx(t + 1.0, f, alpha)) +
               6.0 * (sx(t - 2.0, f, alpha) + sx(t + 2.0, f, alpha)) - sx(t - 3.0, f, alpha) - sx(t + 3.0, f, alpha);
    default: return std::numeric_limits<double>::quiet_NaN();
    }
}

// Basic sum (eq. 10).
double basic_sum(double j, double big_m, double s, double f, int alpha, int d) {
    const double z0 = sz(0.0, f, alpha, d);
    const double zj = sz(j / s, f, alpha, d);
    double sum = z0 * z0 + (1.0 - j / big_m) * zj * zj;
    for (int k = 1; k < static_cast<int>(j); ++k) {
        const double z = sz(k / s, f, alpha, d);
        sum += 2.0 * (1.0 - k / big_m) * z * z;
    }
    return sum;
}

// Tables 1 (modified) and 2 (unmodified): (a0, a1) for 1/edf ~ (1/r)(a0 - a1/r); rows alpha = 2..-4, cols d=1..3.
using Pair = std::array<double, 2>;
constexpr Pair kNa{-1.0, -1.0};
constexpr std::array<std::array<Pair, 3>, 7> kTable1{{
    {{{2.0 / 3.0, 1.0 / 3.0}, {7.0 / 9.0, 1.0 / 2.0}, {22.0 / 25.0, 2.0 / 3.0}}},
    {{{0.840, 0.345}, {0.997, 0.616}, {1.141, 0.843}}},
    {{{1.079, 0.368}, {1.033, 0.607}, {1.184, 0.848}}},
    {{kNa, {1.048, 0.534}, {1.180, 0.816}}},
    {{kNa, {1.302, 0.535}, {1.175, 0.777}}},
    {{kNa, kNa, {1.194, 0.703}}},
    {{kNa, kNa, {1.489, 0.702}}},
}};
constexpr std::array<std::array<Pair, 3>, 7> kTable2{{
    {{{3.0 / 2.0, 1.0 / 2.0}, {35.0 / 18.0, 1.0}, {231.0 / 100.0, 3.0 / 2.0}}},
    {{{78.6, 25.2}, {790.0, 410.0}, {9950.0, 6520.0}}},
    {{{2.0 / 3.0, 1.0 / 6.0}, {2.0 / 3.0, 1.0 / 3.0}, {7.0 / 9.0, 1.0 / 2.0}}},
    {{kNa, {0.852, 0.375}, {0.997, 0.617}}},
    {{kNa, {1.079, 0.368}, {1.033, 0.607}}},
    {{kNa, kNa, {1.053, 0.553}}},
    {{kNa, kNa, {1.302, 0.535}}},
}};
// Table 3 (alpha = 1, unmodified): (b0, b1) of the log(m) correction, d = 1..3.
constexpr std::array<Pair, 3> kTable3{{{6.0, 4.0}, {15.23, 12.0}, {47.8, 40.0}}};

double binomial(int n, int k) {
    return std::exp(std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0));
}

}  // namespace

std::optional<double> edf_greenhall(int alpha, int d, double m, double phase_samples, bool overlapping, bool modified) {
    if (d < 1 || d > 3 || alpha < -4 || alpha > 2 || alpha + 2 * d <= 1 || m < 1.0) return std::nullopt;
    const double f = modified ? 1.0 : m;     // filter factor
    const double s = overlapping ? m : 1.0;  // stride factor
    const double l = m / f + m * d;          // filter length in phase samples
    if (phase_samples < l) return std::nullopt;
    const double big_m = 1.0 + std::floor(s * (phase_samples - l) / m);
    const double j = std::min(big_m, (d + 1) * s);
    const double r = big_m / s;
    const int row = 2 - alpha;
    const int col = d - 1;
    double inv = 0.0;

    if (modified) {  // case 1
        if (j <= kJMax) {
            const double z0 = sz(0.0, 1.0, alpha, d);
            inv = basic_sum(j, big_m, s, 1.0, alpha, d) / (z0 * z0 * big_m);
        } else if (r > d + 1) {
            const Pair a = kTable1[row][col];
            if (a[0] < 0.0) return std::nullopt;
            inv = (a[0] - a[1] / r) / r;
        } else {
            const double z0 = sz(0.0, 1.0, alpha, d);
            inv = basic_sum(kJMax, kJMax, kJMax / r, 1.0, alpha, d) / (z0 * z0 * kJMax);
        }
    } else if (alpha <= 0) {  // case 2
        if (j <= kJMax) {
            const double fp = m * (d + 1) <= kJMax ? m : kInf;
            const double z0 = sz(0.0, fp, alpha, d);
            inv = basic_sum(j, big_m, s, fp, alpha, d) / (z0 * z0 * big_m);
        } else if (r > d + 1) {
            const Pair a = kTable2[row][col];
            if (a[0] < 0.0) return std::nullopt;
            inv = (a[0] - a[1] / r) / r;
        } else {
            const double z0 = sz(0.0, kInf, alpha, d);
            inv = basic_sum(kJMax, kJMax, kJMax / r, kInf, alpha, d) / (z0 * z0 * kJMax);
        }
    } else if (alpha == 1) {  // case 3
        const Pair b = kTable3[col];
        const double b_m = b[0] + b[1] * std::log(m);
        if (j <= kJMax) {
            const double z0 = sz(0.0, m, 1, d);
            inv = basic_sum(j, big_m, s, m, 1, d) / (z0 * z0 * big_m);
        } else if (r > d + 1) {
            const Pair a = kTable2[row][col];
            inv = (a[0] - a[1] / r) / (b_m * b_m * r);
        } else {
            inv = basic_sum(kJMax, kJMax, kJMax / r, kJMax / r, 1, d) / (b_m * b_m * kJMax);
        }
    } else {  // case 4: alpha = 2, unmodified
        if (std::ceil(r) <= d) return std::nullopt;
        const double a0 = binomial(4 * d, 2 * d) / std::pow(binomial(2 * d, d), 2);
        const double a1 = d / 2.0;
        inv = (a0 - a1 / r) / big_m;
    }
    if (!(inv > 0.0) || !std::isfinite(inv)) return std::nullopt;
    return 1.0 / inv;
}

double edf_simple(double n, double m, int alpha) {
    switch (alpha) {
    case 2: return (n + 1.0) * (n - 2.0 * m) / (2.0 * (n - m));
    case 1: {
        const double a = (n - 1.0) / (2.0 * m);
        const double b = (2.0 * m + 1.0) * (n - 1.0) / 4.0;
        return std::exp(std::sqrt(std::log(a) * std::log(b)));
    }
    case 0: return (3.0 * (n - 1.0) / (2.0 * m) - 2.0 * (n - 2.0) / n) * (4.0 * m * m / (4.0 * m * m + 5.0));
    case -1:
        if (m == 1.0) return 2.0 * (n - 2.0) / (2.3 * n - 4.9);
        return 5.0 * n * n / (4.0 * m * (n + 3.0 * m));
    case -2:
        return (n - 2.0) / (m * (n - 3.0) * (n - 3.0)) * ((n - 1.0) * (n - 1.0) - 3.0 * m * (n - 1.0) + 4.0 * m * m);
    default: return n - 1.0;
    }
}

double edf_for(Deviation type, int alpha, double m, double phase_samples) {
    const int d = difference_order(type);
    // Allan variances converge for alpha > -3, Hadamard for alpha > -5 (alpha + 2d > 1).
    const int lowest = d == 2 ? -2 : -4;
    const int a = std::clamp(alpha, lowest, 2);
    const auto edf = edf_greenhall(a, d, m, phase_samples, is_overlapping(type), type == Deviation::mdev);
    if (edf) return *edf;
    return std::max(edf_simple(phase_samples, m, std::clamp(a, -2, 2)), 1.0);
}

ConfidenceInterval confidence_interval(double dev, double edf, double confidence) {
    const double tail = 0.5 * (1.0 - confidence);
    const double chi2_low = chi_square_quantile(tail, edf);
    const double chi2_high = chi_square_quantile(1.0 - tail, edf);
    return {dev * std::sqrt(edf / chi2_high), dev * std::sqrt(edf / chi2_low)};
}

}  // namespace driftlab::host::stats
