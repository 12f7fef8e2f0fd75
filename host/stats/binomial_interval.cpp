// Clopper-Pearson interval; see binomial_interval.hpp.
#include "host/stats/binomial_interval.hpp"

#include <stdexcept>

#include <boost/math/special_functions/beta.hpp>

namespace driftlab::host::stats {

ProportionInterval clopper_pearson(std::size_t k, std::size_t n, double level) {
    if (n == 0 || k > n || !(level > 0.0 && level < 1.0))
        throw std::invalid_argument("clopper_pearson: need 0 <= k <= n, n > 0 and 0 < level < 1");
    const double alpha = 1.0 - level;
    const double kd = static_cast<double>(k), nd = static_cast<double>(n);
    ProportionInterval out;
    out.lower = k == 0 ? 0.0 : boost::math::ibeta_inv(kd, nd - kd + 1.0, alpha / 2.0);
    out.upper = k == n ? 1.0 : boost::math::ibeta_inv(kd + 1.0, nd - kd, 1.0 - alpha / 2.0);
    return out;
}

}  // namespace driftlab::host::stats
