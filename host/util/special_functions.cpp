// Special functions; see special_functions.hpp.
#include "host/util/special_functions.hpp"

#include <cmath>
#include <limits>

#include "host/util/error.hpp"

namespace driftlab::host {
namespace {

constexpr double kEps = 1e-15;
constexpr double kTiny = 1e-300;
constexpr int kMaxIterations = 100000;

/// P(a, x) by its power series; converges fast for x < a + 1.
double gamma_p_series(double a, double x) {
    double term = 1.0 / a;
    double sum = term;
    for (int n = 1; n < kMaxIterations; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::fabs(term) < std::fabs(sum) * kEps) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

/// Q(a, x) by its continued fraction (modified Lentz); converges fast for x >= a + 1.
double gamma_q_fraction(double a, double x) {
    double b = x + 1.0 - a;
    double c = 1.0 / kTiny;
    double d = 1.0 / b;
    double h = d;
    for (int i = 1; i < kMaxIterations; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::fabs(d) < kTiny) d = kTiny;
        c = b + an / c;
        if (std::fabs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < kEps) break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

/// Continued fraction of the incomplete beta (NR betacf), converging for x < (a + 1) / (a + b + 2).
double beta_fraction(double a, double b, double x) {
    const double qab = a + b;
    const double qap = a + 1.0;
    const double qam = a - 1.0;
    double c = 1.0;
    double d = 1.0 - qab * x / qap;
    if (std::fabs(d) < kTiny) d = kTiny;
    d = 1.0 / d;
    double h = d;
    for (int m = 1; m < kMaxIterations; ++m) {
        const int m2 = 2 * m;
        double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
        d = 1.0 + aa * d;
        if (std::fabs(d) < kTiny) d = kTiny;
        c = 1.0 + aa / c;
        if (std::fabs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        h *= d * c;
        aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
        d = 1.0 + aa * d;
        if (std::fabs(d) < kTiny) d = kTiny;
        c = 1.0 + aa / c;
        if (std::fabs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < kEps) break;
    }
    return h;
}

void require(bool ok, const char* what) {
    if (!ok) throw UsageError(what);
}

}  // namespace

double regularized_gamma_p(double a, double x) {
    require(a > 0.0 && x >= 0.0, "regularized_gamma_p: need a > 0 and x >= 0");
    if (x == 0.0) return 0.0;
    return x < a + 1.0 ? gamma_p_series(a, x) : 1.0 - gamma_q_fraction(a, x);
}

double regularized_gamma_q(double a, double x) {
    require(a > 0.0 && x >= 0.0, "regularized_gamma_q: need a > 0 and x >= 0");
    if (x == 0.0) return 1.0;
    return x < a + 1.0 ? 1.0 - gamma_p_series(a, x) : gamma_q_fraction(a, x);
}

double regularized_beta(double a, double b, double x) {
    require(a > 0.0 && b > 0.0 && x >= 0.0 && x <= 1.0, "regularized_beta: need a, b > 0 and 0 <= x <= 1");
    if (x == 0.0 || x == 1.0) return x;
    const double log_front = std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) +
                             b * std::log1p(-x);
    const double front = std::exp(log_front);
    if (x < (a + 1.0) / (a + b + 2.0)) return front * beta_fraction(a, b, x) / a;
    return 1.0 - front * beta_fraction(b, a, 1.0 - x) / b;
}

double chi_square_survival(double x, double dof) {
    require(dof > 0.0, "chi_square_survival: need dof > 0");
    if (x <= 0.0) return 1.0;
    return regularized_gamma_q(0.5 * dof, 0.5 * x);
}

double student_t_cdf(double t, double dof) {
    require(dof > 0.0, "student_t_cdf: need dof > 0");
    // P(|T| > |t|) = I_{dof/(dof+t^2)}(dof/2, 1/2).
    const double tail2 = regularized_beta(0.5 * dof, 0.5, dof / (dof + t * t));
    return t >= 0.0 ? 1.0 - 0.5 * tail2 : 0.5 * tail2;
}

double student_t_quantile(double p, double dof) {
    require(p > 0.0 && p < 1.0 && dof > 0.0, "student_t_quantile: need 0 < p < 1 and dof > 0");
    if (p == 0.5) return 0.0;
    // Bracket, then bisect on the CDF (monotone): robust for every dof, and fast enough for a few calls.
    double lo = 0.0;
    double hi = 1.0;
    const double target = p > 0.5 ? p : 1.0 - p;
    while (student_t_cdf(hi, dof) < target) {
        lo = hi;
        hi *= 2.0;
        if (hi > 1e300) return std::numeric_limits<double>::infinity();
    }
    for (int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (student_t_cdf(mid, dof) < target ? lo : hi) = mid;
    }
    const double q = 0.5 * (lo + hi);
    return p > 0.5 ? q : -q;
}

}  // namespace driftlab::host
