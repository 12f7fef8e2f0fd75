// Clopper-Pearson interval; see binomial_interval.hpp.
#include "host/stats/binomial_interval.hpp"

#include <stdexcept>

#include "host/util/special_functions.hpp"

namespace driftlab::host::stats {

namespace {

// The x with I_x(a, b) = p, by bisection: I_x is monotone in x, and 60 halvings reach double resolution.
double beta_quantile(double p, double a, double b) {
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (regularized_beta(a, b, mid) < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace

ProportionInterval clopper_pearson(std::size_t k, std::size_t n, double level) {
    if (n == 0 || k > n || !(level > 0.0 && level < 1.0))
        throw std::invalid_argument("clopper_pearson: need 0 <= k <= n, n > 0 and 0 < level < 1");
    const double alpha = 1.0 - level;
    const double kd = static_cast<double>(k), nd = static_cast<double>(n);
    ProportionInterval out;
    out.lower = k == 0 ? 0.0 : beta_quantile(alpha / 2.0, kd, nd - kd + 1.0);
    out.upper = k == n ? 1.0 : beta_quantile(1.0 - alpha / 2.0, kd + 1.0, nd - kd);
    return out;
}

}  // namespace driftlab::host::stats
