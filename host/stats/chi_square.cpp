// Chi-square CDF and quantile through the regularized incomplete gamma function of host/util (docs/allan.md §4).
#include "host/stats/chi_square.hpp"

#include "host/util/special_functions.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace driftlab::host::stats {
namespace {

// Standard normal quantile by bisection on erfc: only used for a starting point.
double normal_quantile(double p) {
    double lo = -40.0;
    double hi = 40.0;
    for (int i = 0; i < 200 && hi - lo > 1e-12; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace

double chi_square_cdf(double x, double dof) { return regularized_gamma_p(0.5 * dof, 0.5 * x); }

double chi_square_quantile(double p, double dof) {
    if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("chi-square quantile: p must be in (0, 1)");
    if (!(dof > 0.0) || !std::isfinite(dof)) throw std::invalid_argument("chi-square quantile: dof must be > 0");
    const double a = 0.5 * dof;

    // Wilson-Hilferty start (NIST SP 1065 sec. 5.3), clamped positive.
    const double z = normal_quantile(p);
    const double k = 2.0 / (9.0 * dof);
    const double wh = dof * std::pow(std::fmax(1.0 - k + z * std::sqrt(k), 1e-3), 3.0);
    double y = 0.5 * wh;  // in gamma units: x = 2y

    // f(y) = P(a, y) - p, increasing; in the upper tail it is evaluated as (1 - p) - Q(a, y) so that a
    // quantile near 1 keeps its relative accuracy.
    const bool upper = p > 0.5;
    const auto f_of = [&](double yy) { return upper ? (1.0 - p) - regularized_gamma_q(a, yy) : regularized_gamma_p(a, yy) - p; };

    // Bracket [lo, hi] with f(lo) <= 0 <= f(hi).
    double lo = 0.0;
    double hi = y;
    while (f_of(hi) < 0.0) {
        lo = hi;
        hi = 2.0 * hi + 1.0;
    }
    const double lga = std::lgamma(a);
    for (int i = 0; i < 300; ++i) {
        const double f = f_of(y);
        if (f < 0.0) lo = y; else hi = y;
        const double density = std::exp(-y + (a - 1.0) * std::log(y) - lga);
        double next = (density > 0.0 && std::isfinite(density)) ? y - f / density : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        const double step = std::fabs(next - y);
        y = next;
        if (step <= 1e-14 * y || hi - lo <= 1e-15 * hi) break;
    }
    return 2.0 * y;
}

}  // namespace driftlab::host::stats
