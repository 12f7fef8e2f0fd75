// Ljung–Box test; see ljung_box.hpp.
#include "host/stats/ljung_box.hpp"

#include <algorithm>

#include "host/stats/chi_square.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::stats {

LjungBoxResult ljung_box(const std::vector<double>& rho, std::size_t n, std::size_t lags, std::size_t fitted_dof) {
    if (lags == 0 || lags >= n || rho.size() <= lags || fitted_dof >= lags)
        throw UsageError("ljung_box: need 0 < fitted_dof < lags < n and lags + 1 autocorrelation values");
    LjungBoxResult out;
    out.lags = lags;
    const double nd = static_cast<double>(n);
    double sum = 0.0;
    for (std::size_t k = 1; k <= lags; ++k) sum += rho[k] * rho[k] / (nd - static_cast<double>(k));
    out.statistic = nd * (nd + 2.0) * sum;
    out.dof = static_cast<double>(lags - fitted_dof);
    out.p_value = chi_square_survival(out.statistic, out.dof);
    return out;
}

std::size_t default_ljung_box_lags(std::size_t n) { return std::max<std::size_t>(1, std::min<std::size_t>(20, n / 5)); }

}  // namespace driftlab::host::stats
