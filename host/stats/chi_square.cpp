// Chi-square CDF and quantile (docs/allan.md §4), from Boost.Math.
#include "host/stats/chi_square.hpp"

#include <cmath>
#include <stdexcept>

#include <boost/math/distributions/chi_squared.hpp>

namespace driftlab::host::stats {

double chi_square_cdf(double x, double dof) {
    if (!(dof > 0.0) || !std::isfinite(dof)) throw std::invalid_argument("chi-square cdf: dof must be > 0");
    return x <= 0.0 ? 0.0 : boost::math::cdf(boost::math::chi_squared(dof), x);
}

double chi_square_survival(double x, double dof) {
    if (!(dof > 0.0) || !std::isfinite(dof)) throw std::invalid_argument("chi-square survival: dof must be > 0");
    return x <= 0.0 ? 1.0 : boost::math::cdf(boost::math::complement(boost::math::chi_squared(dof), x));
}

double chi_square_quantile(double p, double dof) {
    if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("chi-square quantile: p must be in (0, 1)");
    if (!(dof > 0.0) || !std::isfinite(dof)) throw std::invalid_argument("chi-square quantile: dof must be > 0");
    // The upper tail through the complement keeps a quantile near 1 at its relative accuracy.
    const boost::math::chi_squared dist(dof);
    return p > 0.5 ? boost::math::quantile(boost::math::complement(dist, 1.0 - p)) : boost::math::quantile(dist, p);
}

}  // namespace driftlab::host::stats
